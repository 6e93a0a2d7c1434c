/* Sets the wall clock for the virtual board's screen power test, and
 * whether the kernel counts it as synchronised (what NTP would make it):
 *   clock_set "2026-11-23 08:59:40" synced|unsynced
 * The time is UTC. Setting the time marks the clock unsynchronised, as
 * settimeofday does; "synced" then clears STA_UNSYNC with a small maximum
 * error, as an NTP daemon does. */
#include <stdio.h>
#include <string.h>
#include <sys/timex.h>
#include <time.h>

int main(int argc, char **argv)
{
	struct tm tm = {0};
	struct timespec ts = {0};
	struct timex tx = {0};

	if (argc != 3 || !strptime(argv[1], "%Y-%m-%d %H:%M:%S", &tm)) {
		fprintf(stderr, "usage: %s 'YYYY-MM-DD HH:MM:SS' synced|unsynced\n", argv[0]);
		return 2;
	}
	ts.tv_sec = timegm(&tm);
	if (clock_settime(CLOCK_REALTIME, &ts)) {
		perror("clock_settime");
		return 1;
	}
	tx.modes = ADJ_STATUS | ADJ_MAXERROR | ADJ_ESTERROR;
	tx.status = strcmp(argv[2], "synced") ? STA_UNSYNC : 0;
	if (adjtimex(&tx) < 0) {
		perror("adjtimex");
		return 1;
	}
	tx = (struct timex){0};
	printf("%s\n", adjtimex(&tx) == TIME_ERROR ? "unsynced" : "synced");
	return 0;
}
