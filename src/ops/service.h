/* Talking to systemd (Type=notify): READY=1 once the first frame is on the
 * screen, RELOADING=1 around a reload, STOPPING=1, and WATCHDOG=1 from the
 * live loop at half the interval systemd asked for, so that a loop stuck
 * in the GPU driver, or a display that never completes a page flip, gets
 * the service restarted. Outside systemd every call does nothing. */
#ifndef MK_SERVICE_H
#define MK_SERVICE_H

#include <stdbool.h>
#include <stdint.h>

struct service {
	uint64_t ping_ns;   /* half of WatchdogSec=; 0: no watchdog */
	uint64_t next_ping; /* CLOCK_MONOTONIC ns */
	bool ready;	    /* READY=1 was sent */
	bool shown;	    /* ... and a frame has been on the screen since */
	bool stalled;	    /* a missed ping was logged */
};

void service_init(struct service *s, uint64_t now_ns);
/* shown: the first frame is on the screen (the backend reported it).
 * Else there is no display to show it on, and waiting for one is the
 * running state: READY=1 too, with a status that says so. */
void service_ready(struct service *s, bool shown);
void service_reloading(bool done);
void service_stopping(void);
/* When service_ping next wants to run, or UINT64_MAX. */
uint64_t service_deadline(const struct service *s);
/* Ping now, before something long such as a reload. */
void service_keepalive(struct service *s, uint64_t now_ns);
/* Ping the watchdog when due. healthy false: the display has made no
 * progress for longer than the interval, so no ping is sent and systemd
 * restarts the service when the interval ends. */
void service_ping(struct service *s, uint64_t now_ns, bool healthy);

#endif
