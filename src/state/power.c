#include "state/power.h"

#define NS_PER_S 1000000000.0

static uint64_t after(uint64_t t, double seconds)
{
	return t + (uint64_t)(seconds * NS_PER_S);
}

/* How long an input outside the schedule keeps the screen on. */
static double wake_s(const struct power_state *p)
{
	return p->cfg.blank_after_s > 0 ? p->cfg.blank_after_s : 60.0;
}

static enum power_reason decide(const struct power_state *p, const struct power_clock *c)
{
	bool schedule = p->cfg.schedule.count > 0;
	bool idle =
	    p->cfg.blank_after_s > 0 && c->now_ns >= after(p->last_input_ns, p->cfg.blank_after_s);

	if (p->remote_off)
		return POWER_REMOTE_OFF;

	if (schedule && c->synced && !schedule_on(&p->cfg.schedule, c->wday, c->minute)) {
		if (p->woken_ns != CLOCK_NEVER && c->now_ns < after(p->woken_ns, wake_s(p)))
			return POWER_WOKEN;
		return POWER_SCHEDULED_OFF;
	}
	if (idle)
		return POWER_IDLE;
	if (schedule)
		return c->synced ? POWER_SCHEDULED_ON : POWER_NO_CLOCK;
	return POWER_ALWAYS;
}

static bool reason_on(enum power_reason r)
{
	return r != POWER_SCHEDULED_OFF && r != POWER_IDLE && r != POWER_REMOTE_OFF;
}

void power_init(struct power_state *p, const struct power_config *cfg, const struct power_clock *c)
{
	*p = (struct power_state){.cfg = *cfg, .last_input_ns = c->now_ns, .woken_ns = CLOCK_NEVER};
	p->reason = decide(p, c);
	p->on = reason_on(p->reason);
}

unsigned power_update(struct power_state *p, const struct power_clock *c)
{
	enum power_reason r = decide(p, c);
	unsigned bits = 0;

	if (r == POWER_NO_CLOCK && !p->said_unsynced) {
		p->said_unsynced = true;
		bits |= POWER_SAY_UNSYNCED;
	}
	if (reason_on(r) != p->on)
		bits |= POWER_CHANGED;
	p->on = reason_on(r);
	p->reason = r;
	return bits;
}

unsigned power_input(struct power_state *p, const struct power_clock *c)
{
	p->last_input_ns = c->now_ns;
	p->remote_off = false;
	if (p->cfg.schedule.count && c->synced &&
	    !schedule_on(&p->cfg.schedule, c->wday, c->minute))
		p->woken_ns = c->now_ns;
	return power_update(p, c);
}

unsigned power_remote(struct power_state *p, const struct power_clock *c, bool on)
{
	if (on)
		return power_input(p, c);
	p->remote_off = true;
	return power_update(p, c);
}

uint64_t power_deadline(const struct power_state *p)
{
	if (p->reason == POWER_WOKEN)
		return after(p->woken_ns, wake_s(p));
	if (p->on && p->cfg.blank_after_s > 0)
		return after(p->last_input_ns, p->cfg.blank_after_s);
	return CLOCK_NEVER;
}

const char *power_reason_name(enum power_reason r)
{
	static const char *const names[] = {
	    [POWER_ALWAYS] = "always on",
	    [POWER_SCHEDULED_ON] = "inside the schedule",
	    [POWER_NO_CLOCK] = "on: the clock is not synchronised, the schedule waits for it",
	    [POWER_WOKEN] = "woken by an input outside the schedule",
	    [POWER_SCHEDULED_OFF] = "outside the schedule",
	    [POWER_IDLE] = "blanked: no input for blank_after",
	    [POWER_REMOTE_OFF] = "off by remote control until an input or 'screen on'",
	};

	return (unsigned)r < sizeof(names) / sizeof(names[0]) ? names[r] : "?";
}
