#include "ops/screen.h"
#include "state/power.h"
#include "display/backlight.h"
#include "display/cec_link.h"
#include "util/log.h"

#include <stdlib.h>
#include <string.h>
#include <sys/timex.h>
#include <time.h>

#define NS_PER_S 1000000000ull

struct screen {
	struct power_state power;
	struct display *display;
	struct backlight *backlight;
	struct cec_link *cec; /* on its own thread: the bus may take seconds */
	bool scheduled;	      /* a schedule is set: decide again each minute */
};

/* The wall clock as power.c reads it. The kernel keeps STA_UNSYNC set
 * until NTP (systemd-timesyncd, chrony) has disciplined the clock, which
 * is what timedatectl shows as "System clock synchronized". */
static struct power_clock wall_clock(uint64_t now_ns)
{
	struct timex tx = {0};
	struct power_clock c = {.now_ns = now_ns};
	time_t t = time(NULL);
	struct tm tm;
	int state = adjtimex(&tx);

	localtime_r(&t, &tm);
	c.wday = tm.tm_wday;
	c.minute = tm.tm_hour * 60 + tm.tm_min;
	c.synced = state != TIME_ERROR && !(tx.status & STA_UNSYNC);
	return c;
}

static void apply(struct screen *s)
{
	bool on = s->power.on;

	log_info("screen %s: %s", on ? "on" : "off", power_reason_name(s->power.reason));
	if (s->display->set_power)
		s->display->set_power(s->display, on);
	if (s->backlight)
		backlight_power(s->backlight, on);
	if (s->cec)
		cec_link_power(s->cec, on);
}

struct screen *screen_new(const struct screen_config *cfg, struct display *d, uint64_t now_ns)
{
	struct screen *s = calloc(1, sizeof(*s));
	struct power_config pc = {.blank_after_s = cfg->blank_after * 60};
	struct power_clock c = wall_clock(now_ns);
	char err[160];

	if (!s)
		return NULL;
	if (cfg->schedule && *cfg->schedule &&
	    schedule_parse(&pc.schedule, cfg->schedule, err, sizeof(err))) {
		log_err("[power] schedule = %s: %s", cfg->schedule, err);
		free(s);
		return NULL;
	}
	s->display = d;
	s->scheduled = pc.schedule.count > 0;
	if (s->scheduled || cfg->blank_after > 0)
		s->backlight = backlight_new("/sys/class/backlight");
	if (cfg->cec)
		s->cec = cec_link_new(cfg->cec_device ? cfg->cec_device : "/dev/cec0");
	power_init(&s->power, &pc, &c);
	if (!s->power.on)
		apply(s);
	return s;
}

void screen_free(struct screen *s)
{
	if (!s)
		return;
	/* Whoever comes next finds the screen on. */
	if (!s->power.on) {
		s->power.on = true;
		if (s->backlight)
			backlight_power(s->backlight, true);
	}
	backlight_free(s->backlight);
	cec_link_free(s->cec);
	free(s);
}

bool screen_input(struct screen *s, uint64_t now_ns)
{
	struct power_clock c = wall_clock(now_ns);
	bool was_on = s->power.on;

	power_input(&s->power, &c);
	if (s->power.on != was_on)
		apply(s);
	return !was_on && s->power.on;
}

bool screen_remote(struct screen *s, bool on, uint64_t now_ns)
{
	struct power_clock c = wall_clock(now_ns);
	bool was_on = s->power.on;

	if (power_remote(&s->power, &c, on) & POWER_CHANGED)
		apply(s);
	return !was_on && s->power.on;
}

bool screen_update(struct screen *s, uint64_t now_ns)
{
	struct power_clock c = wall_clock(now_ns);
	bool was_on = s->power.on;
	unsigned bits = power_update(&s->power, &c);

	if (bits & POWER_SAY_UNSYNCED)
		log_warn("screen: the system clock is not synchronised (timedatectl); the "
			 "schedule waits for it and the screen stays on");
	if (bits & POWER_CHANGED)
		apply(s);
	return !was_on && s->power.on;
}

bool screen_on(const struct screen *s)
{
	return s->power.on;
}

uint64_t screen_deadline(const struct screen *s, uint64_t now_ns)
{
	uint64_t d = power_deadline(&s->power);
	time_t t;
	uint64_t next_minute;

	if (!s->scheduled)
		return d;
	/* Local minutes start on whole UTC minutes in every time zone
	 * that matters here, and a DST change moves whole hours. */
	t = time(NULL);
	next_minute = now_ns + (uint64_t)(60 - t % 60) * NS_PER_S;
	return next_minute < d ? next_minute : d;
}
