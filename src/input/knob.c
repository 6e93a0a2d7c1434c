#include "input/knob.h"

#include <linux/input-event-codes.h>
#include <stdlib.h>

const char *const knob_turns_names[KNOB_TURNS_COUNT + 1] = {"model", "stops", NULL};

/* What a detent does, anticlockwise and clockwise, by [knob] turns. */
static const enum app_action turn_actions[KNOB_TURNS_COUNT][2] = {
    [KNOB_TURNS_MODEL] = {ACTION_TURN_LEFT, ACTION_TURN_RIGHT},
    [KNOB_TURNS_STOPS] = {ACTION_PREV_STOP, ACTION_NEXT_STOP},
};

int knob_axis(const bool *has, int count)
{
	static const unsigned order[] = {REL_DIAL, REL_WHEEL, REL_X};

	for (size_t i = 0; i < sizeof(order) / sizeof(order[0]); i++)
		if ((int)order[i] < count && has[order[i]])
			return (int)order[i];
	return -1;
}

void knob_decoder_init(struct knob_decoder *d, const struct knob_config *c, unsigned axis,
		       int per_detent)
{
	struct button_config key = {
	    .press = c->press, .long_press = c->long_press, .long_ns = KNOB_LONG_NS};

	/* The kernel debounces the key (gpio-keys): every edge counts. */
	*d = (struct knob_decoder){.turns = c->turns < KNOB_TURNS_COUNT ? c->turns : 0,
				   .step = c->step,
				   .axis = axis,
				   .per_detent = per_detent > 0 ? per_detent : 1};
	button_init(&d->key, &key, false);
}

/* The report is complete: its whole detents, one event each. */
static int detents(struct knob_decoder *d, uint64_t t, struct app_event *out)
{
	int whole = d->counts / d->per_detent, n = abs(whole);
	enum app_action act = turn_actions[d->turns][whole > 0];

	d->counts -= whole * d->per_detent;
	if (n > KNOB_MAX_EVENTS)
		n = KNOB_MAX_EVENTS;
	for (int i = 0; i < n; i++)
		out[i] = (struct app_event){.time_ns = t,
					    .action = act,
					    .pressed = true,
					    .angle = d->turns == KNOB_TURNS_MODEL ? d->step : 0};
	return n;
}

static bool is_key(unsigned code)
{
	return code == KEY_ENTER || code == KEY_KPENTER || code == KEY_SELECT || code == BTN_0;
}

int knob_decoder_event(struct knob_decoder *d, uint64_t time_ns, unsigned type, unsigned code,
		       int value, struct app_event *out)
{
	if (type == EV_REL && code == d->axis) {
		/* A turn back starts afresh: half a detent one way and
		 * half the other is no detent. */
		if ((d->counts > 0 && value < 0) || (d->counts < 0 && value > 0))
			d->counts = 0;
		d->counts += value;
		return 0;
	}
	if (type == EV_SYN && code == SYN_REPORT)
		return detents(d, time_ns, out);
	/* value 2 is the key's autorepeat: the long press is the button's. */
	if (type == EV_KEY && is_key(code) && value != 2)
		return button_edge(&d->key, time_ns, value == 1, out);
	return 0;
}

int knob_decoder_timeout(struct knob_decoder *d, uint64_t now_ns, struct app_event *out)
{
	return button_timeout(&d->key, now_ns, out);
}

uint64_t knob_decoder_deadline(const struct knob_decoder *d)
{
	return button_deadline(&d->key);
}

int knob_decoder_lost(struct knob_decoder *d, uint64_t now_ns, struct app_event *out)
{
	d->counts = 0;
	return button_lost(&d->key, now_ns, out);
}
