/* Logging: one line per message, with the systemd priority prefix when the
 * journal reads our stderr, so `journalctl -p err` filters correctly. */
#ifndef MK_LOG_H
#define MK_LOG_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum log_level { LOG_ERR = 3, LOG_WARN = 4, LOG_INFO = 6, LOG_DEBUG = 7 };

/* The levels a user can pick, quietest first, and the names the settings
 * give them ("error", "warning", "info", "debug"; then NULL). */
#define LOG_LEVELS 4
extern const enum log_level log_levels[LOG_LEVELS];
extern const char *const log_level_names[LOG_LEVELS + 1];

/* Set at start-up, before anything else runs, and again by a reload. */
void log_set_level(enum log_level max);
/* For a helper process, which is told the level on its command line. */
enum log_level log_get_level(void);
/* A copy of the last error logged into buf, or "" when none was. */
void log_last_error(char *buf, size_t size);
/* When it was logged, in seconds since the epoch (wall clock, for the
 * metrics: a dashboard compares it with other machines'); 0 when none
 * (or since log_clear_last_error). */
double log_last_error_time(void);
/* Forget it: a reload starts afresh, so that --status names a failure
 * of this reload only, and nothing after a good one. */
void log_clear_last_error(void);
/* How many warnings this thread has logged (at any level set): a load
 * that warned is not cached, so that each start says it again. */
unsigned log_warnings(void);
void log_msg(enum log_level level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

#define log_err(...)   log_msg(LOG_ERR, __VA_ARGS__)
#define log_warn(...)  log_msg(LOG_WARN, __VA_ARGS__)
#define log_info(...)  log_msg(LOG_INFO, __VA_ARGS__)
#define log_debug(...) log_msg(LOG_DEBUG, __VA_ARGS__)

#ifdef __cplusplus
}
#endif

#endif
