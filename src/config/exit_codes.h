/* The program's exit statuses, in one list: the code returns them
 * (app/main.c, ops/check.c), matcap-kiosk(1)'s EXIT STATUS is written from
 * it (config/settings_man.c), and tests/e2e/exit_claims.sh holds README.md
 * and docs/ to it, so that no document states a status the program does
 * not return. Numbers above 2 are those of sysexits.h; the unit's
 * RestartPreventExitStatus= names those a restart cannot fix (77, 78).
 *
 * Each row: the name (EXIT_CODE_name), the number, what it means (plain
 * text for the manual), and the words a document uses for that case (an
 * extended regular expression, matched without case; "" for none): a
 * sentence that states an exit status beside such words must state one
 * whose row has them. */
#ifndef MK_EXIT_CODES_H
#define MK_EXIT_CODES_H

#define EXIT_CODE_ROWS(X)                                                                          \
	X(OK, 0,                                                                                   \
	  "ended cleanly (SIGTERM, SIGINT), the frames were drawn (--output), the settings are "   \
	  "valid (--check-config), or --import had nothing to import",                             \
	  "success|cleanly|nothing to import")                                                     \
	X(FAILED, 1,                                                                               \
	  "an error, said on standard error: a model or image that cannot be read, an output "     \
	  "that cannot be written, a display that does not open for a reason other than those "    \
	  "of 69, 75 and 77, no kiosk answering --status, a file of --import that does not copy "  \
	  "or load",                                                                               \
	  "no kiosk answers|does not copy")                                                        \
	X(USAGE, 2, "a bad command line: an unknown option, or a value it does not take",          \
	  "bad option|command line|unknown option")                                                \
	X(NOINPUT, 66,                                                                             \
	  "(--check-config) the settings are right, but a file they name is missing or does not "  \
	  "load",                                                                                  \
	  "missing|does not load")                                                                 \
	X(UNAVAILABLE, 69, "no display to open (no DRM device, or no output of that name)",        \
	  "display fail|no display|display .*(absent|not open|cannot be opened)")                  \
	X(TEMPFAIL, 75,                                                                            \
	  "the display is busy (another program is DRM master) and [display] on_busy = exit",      \
	  "busy|display fail|display .*cannot be opened")                                          \
	X(NOPERM, 77,                                                                              \
	  "the display is forbidden (the user is not in the video group); the service is not "     \
	  "restarted",                                                                             \
	  "forbidden|permission|display fail|display .*cannot be opened")                          \
	X(CONFIG, 78,                                                                              \
	  "a bad setting, named with its file and line (also two buttons on one line, or what a "  \
	  "USB stick may not set in --import); the service is not restarted",                      \
	  "config(uration)? (file|error)|bad setting|has an error|may not")

#define EXIT_CODE_ENUM(name, number, means, words) EXIT_CODE_##name = number,
enum exit_code { EXIT_CODE_ROWS(EXIT_CODE_ENUM) };
#undef EXIT_CODE_ENUM

#endif
