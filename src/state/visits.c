#include "state/visits.h"

#include "state/view.h"

#include <stdio.h>
#include <string.h>

static const char *const touch_names[] = {"drag", "pinch", "tap"};

const char *visits_action_name(int action)
{
	if (action >= 0 && action < ACTION_COUNT)
		return app_action_names[action];
	if (action >= ACTION_COUNT && action < VISITS_ACTIONS)
		return touch_names[action - ACTION_COUNT];
	return "?";
}

static struct visit_slot *slot(struct visits *v, const char *kind, const char *name)
{
	struct visit_slot *s;

	for (int i = 0; i < v->slot_count; i++) {
		s = &v->slots[i];
		if (!strncmp(s->kind, kind, VISITS_KIND - 1) &&
		    !strncmp(s->name, name, VISITS_NAME - 1))
			return s;
	}
	if (v->slot_count == VISITS_SLOTS)
		return NULL;
	s = &v->slots[v->slot_count++];
	snprintf(s->kind, sizeof(s->kind), "%s", kind);
	snprintf(s->name, sizeof(s->name), "%s", name);
	s->seconds = 0;
	return s;
}

int visit_time_add(struct visits *v, const char *kind, const char *name, double seconds)
{
	struct visit_slot *s = slot(v, kind, name ? name : "");

	if (!s) {
		v->dropped_s += seconds;
		return -1;
	}
	s->seconds += seconds;
	return 0;
}

double visits_seconds(const struct visits *v, const char *kind, const char *name)
{
	for (int i = 0; i < v->slot_count; i++)
		if (!strcmp(v->slots[i].kind, kind) && !strcmp(v->slots[i].name, name))
			return v->slots[i].seconds;
	return 0;
}

/* The time since the last observation to what was shown, up to t. A
 * stop, a hotspot and a language count while a visitor is there: attract
 * mode's tour of them is attract mode's time. A hotspot's view is no
 * stop the curator wrote: its time is the hotspot's alone. */
static void account(struct visits *v, uint64_t t)
{
	char name[16];
	double s;

	if (!v->observed_ns || t <= v->observed_ns)
		return;
	s = (double)(t - v->observed_ns) * 1e-9;
	v->observed_ns = t;
	if (v->attract) {
		visit_time_add(v, "attract", "", s);
		return;
	}
	if (v->stop > 0 && v->stop <= FRAME_STOPS) {
		snprintf(name, sizeof(name), "%d", v->stop);
		visit_time_add(v, "stop", name, s);
	}
	if (v->hotspot[0])
		visit_time_add(v, "hotspot", v->hotspot, s);
	if (v->lang[0])
		visit_time_add(v, "language", v->lang, s);
}

/* Any input: a visit begins when the kiosk was idle; attract mode ends. */
static void input(struct visits *v, uint64_t t, double idle_s)
{
	uint64_t idle_ns = (uint64_t)((idle_s > 0 ? idle_s : VISITS_IDLE_S) * 1e9);

	account(v, t);
	if (!v->any_input || v->attract || t >= v->last_input_ns + idle_ns)
		v->count++;
	v->any_input = true;
	if (t > v->last_input_ns)
		v->last_input_ns = t;
	v->attract = false;
}

void visits_press(struct visits *v, enum input_kind kind, const struct app_event *ev, double idle_s)
{
	input(v, ev->time_ns, idle_s);
	if (ev->pressed && kind < INPUT_KINDS && ev->action > ACTION_NONE &&
	    ev->action < ACTION_COUNT)
		v->presses[kind][ev->action]++;
}

/* What a gesture counts as; -1: nothing (the moves of a drag counted). */
static int touch_action(struct visits *v, const struct gesture *g, enum app_action long_press)
{
	bool was = v->touch_moving;

	switch (g->kind) {
	case GESTURE_DRAG:
	case GESTURE_PINCH:
		v->touch_moving = true;
		return was ? -1 : g->kind == GESTURE_DRAG ? VISITS_DRAG : VISITS_PINCH;
	case GESTURE_END:
		v->touch_moving = false;
		return -1;
	case GESTURE_TAP:
		return VISITS_TAP;
	case GESTURE_DOUBLE_TAP:
		return ACTION_RESET;
	case GESTURE_LONG_PRESS:
		return long_press > ACTION_NONE && long_press < ACTION_COUNT ? (int)long_press
									     : VISITS_TAP;
	}
	return -1;
}

void visits_touch(struct visits *v, const struct gesture *g, enum app_action long_press,
		  double idle_s)
{
	int action = touch_action(v, g, long_press);

	input(v, g->time_ns, idle_s);
	if (action >= 0)
		v->presses[INPUT_KIND_TOUCH][action]++;
}

void visits_observe(struct visits *v, uint64_t now_ns, const struct visit_view *w)
{
	account(v, now_ns);
	if (!v->observed_ns)
		v->observed_ns = now_ns;
	v->stop = w->stop + 1;
	v->attract = w->attract;
	snprintf(v->hotspot, sizeof(v->hotspot), "%s", w->hotspot ? w->hotspot : "");
	snprintf(v->lang, sizeof(v->lang), "%s", w->lang ? w->lang : "");
}
