#include "ops/service.h"
#include "util/log.h"

#include <systemd/sd-daemon.h>

void service_init(struct service *s, uint64_t now_ns)
{
	uint64_t usec = 0;

	*s = (struct service){0};
	/* Only when WATCHDOG_PID names this process, so a child we start
	 * cannot inherit the duty. */
	if (sd_watchdog_enabled(0, &usec) > 0 && usec > 0) {
		s->ping_ns = usec * 1000 / 2;
		s->next_ping = now_ns;
		log_info("systemd watchdog: %.1f s, pinged every %.1f s", usec / 1e6,
			 s->ping_ns / 1e9);
	}
}

void service_ready(struct service *s, bool shown)
{
	if (s->ready && (s->shown || !shown))
		return;
	if (shown)
		sd_notify(0, "READY=1\nSTATUS=showing the scene");
	else
		sd_notify(0, "READY=1\nSTATUS=waiting for a display");
	log_info("%s", shown ? "ready: the first frame is on the screen"
			     : "ready: waiting for a display to show the scene on");
	s->ready = true;
	s->shown = shown;
}

void service_reloading(bool done)
{
	sd_notify(0, done ? "READY=1\nSTATUS=reloaded" : "RELOADING=1\nSTATUS=reloading");
}

void service_stopping(void)
{
	sd_notify(0, "STOPPING=1");
}

uint64_t service_deadline(const struct service *s)
{
	return s->ping_ns ? s->next_ping : UINT64_MAX;
}

void service_keepalive(struct service *s, uint64_t now_ns)
{
	if (!s->ping_ns)
		return;
	s->next_ping = now_ns + s->ping_ns;
	sd_notify(0, "WATCHDOG=1");
}

void service_ping(struct service *s, uint64_t now_ns, bool healthy)
{
	if (!s->ping_ns || now_ns < s->next_ping)
		return;
	s->next_ping = now_ns + s->ping_ns;
	if (!healthy) {
		if (!s->stalled)
			log_err("the display has shown no frame for %.1f s: no watchdog ping, "
				"systemd will restart the kiosk",
				s->ping_ns / 1e9);
		s->stalled = true;
		return;
	}
	s->stalled = false;
	sd_notify(0, "WATCHDOG=1");
}
