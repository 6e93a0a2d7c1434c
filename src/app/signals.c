#include "app/signals.h"
#include "util/log.h"

#include <errno.h>
#include <signal.h>
#include <stdbool.h>
#include <string.h>
#include <sys/signalfd.h>
#include <unistd.h>

static void loop_signals(sigset_t *set)
{
	sigemptyset(set);
	sigaddset(set, SIGTERM);
	sigaddset(set, SIGINT);
	sigaddset(set, SIGHUP);
}

int signals_block(void)
{
	sigset_t set;

	loop_signals(&set);
	return sigprocmask(SIG_BLOCK, &set, NULL) ? -errno : 0;
}

int signals_unblock(void)
{
	sigset_t set;

	loop_signals(&set);
	return sigprocmask(SIG_UNBLOCK, &set, NULL) ? -errno : 0;
}

int signals_open(void)
{
	sigset_t set;
	int fd;

	loop_signals(&set);
	fd = signalfd(-1, &set, SFD_CLOEXEC | SFD_NONBLOCK);
	return fd < 0 ? -errno : fd;
}

enum signals_seen signals_read(int fd)
{
	struct signalfd_siginfo si;
	bool quit = false, hup = false;

	while (read(fd, &si, sizeof(si)) == sizeof(si)) {
		if (si.ssi_signo == SIGHUP) {
			hup = true;
			continue;
		}
		log_info("%s: shutting down", strsignal((int)si.ssi_signo));
		quit = true;
	}
	return quit ? SIGNALS_QUIT : hup ? SIGNALS_HUP : SIGNALS_NONE;
}
