/* The signals the kiosk's loop reads (SIGTERM, SIGINT, SIGHUP): blocked
 * before any thread starts, then read through a signalfd, so that no
 * thread takes one with its default action and a handler never runs in
 * the middle of a frame. */
#ifndef MK_SIGNALS_H
#define MK_SIGNALS_H

/* Block them. Call it before any thread starts (the GL driver's). */
int signals_block(void);
int signals_unblock(void);
/* A non-blocking signalfd for them, or -errno. */
int signals_open(void);

enum signals_seen { SIGNALS_NONE, SIGNALS_QUIT, SIGNALS_HUP };
/* What the signals queued on fd ask: a quit wins over SIGHUPs, and
 * SIGHUPs queued together are one. Logs a quit. */
enum signals_seen signals_read(int fd);

#endif
