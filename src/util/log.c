#include "util/log.h"

#include <errno.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* The level is set from main() and again by a reload, while the content
 * worker logs: an atomic. The journal check is pure (it reads the
 * environment each time), so no other state is kept. */
static atomic_int max_level = LOG_INFO;
/* The last error line, for the kiosk's status report (--status): the one
 * other thing kept, as the level is, for the whole process. The model
 * loader's thread logs too: a lock, and the reader gets a copy. */
static char last_error[1024];
static double last_error_at; /* wall clock, seconds since the epoch; 0: none */
static pthread_mutex_t last_error_lock = PTHREAD_MUTEX_INITIALIZER;

const enum log_level log_levels[LOG_LEVELS] = {LOG_ERR, LOG_WARN, LOG_INFO, LOG_DEBUG};
const char *const log_level_names[LOG_LEVELS + 1] = {"error", "warning", "info", "debug", NULL};

void log_set_level(enum log_level max)
{
	atomic_store_explicit(&max_level, (int)max, memory_order_relaxed);
}

enum log_level log_get_level(void)
{
	return (enum log_level)atomic_load_explicit(&max_level, memory_order_relaxed);
}

static const char *level_word(enum log_level level)
{
	switch (level) {
	case LOG_ERR:
		return "error: ";
	case LOG_WARN:
		return "warning: ";
	default:
		return "";
	}
}

/* This thread's warnings, logged or not (log_warnings). */
static _Thread_local unsigned warnings;

unsigned log_warnings(void)
{
	return warnings;
}

/* errno is kept: a caller may log, then return -errno. */
void log_msg(enum log_level level, const char *fmt, ...)
{
	int saved_errno = errno;
	char line[1024];
	va_list ap;

	warnings += level == LOG_WARN;
	if ((int)level > atomic_load_explicit(&max_level, memory_order_relaxed))
		return;
	va_start(ap, fmt);
	vsnprintf(line, sizeof(line), fmt, ap);
	va_end(ap);
	if (level == LOG_ERR) {
		struct timespec ts;

		clock_gettime(CLOCK_REALTIME, &ts);
		pthread_mutex_lock(&last_error_lock);
		snprintf(last_error, sizeof(last_error), "%s", line);
		last_error_at = (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
		pthread_mutex_unlock(&last_error_lock);
	}
	/* systemd sets JOURNAL_STREAM when stderr goes to the journal: then
	 * the <N> prefix carries the priority and the name is added by it. */
	if (getenv("JOURNAL_STREAM"))
		fprintf(stderr, "<%d>%s\n", (int)level, line);
	else
		fprintf(stderr, "matcap-kiosk: %s%s\n", level_word(level), line);
	errno = saved_errno;
}

void log_clear_last_error(void)
{
	pthread_mutex_lock(&last_error_lock);
	last_error[0] = '\0';
	last_error_at = 0;
	pthread_mutex_unlock(&last_error_lock);
}

void log_last_error(char *buf, size_t size)
{
	pthread_mutex_lock(&last_error_lock);
	snprintf(buf, size, "%s", last_error);
	pthread_mutex_unlock(&last_error_lock);
}

double log_last_error_time(void)
{
	double at;

	pthread_mutex_lock(&last_error_lock);
	at = last_error_at;
	pthread_mutex_unlock(&last_error_lock);
	return at;
}
