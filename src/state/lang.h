/* Which language the texts are shown in ([caption] languages): the
 * visitor's choice (next-language steps through them), until the kiosk
 * is idle for idle_seconds; then attract mode shows each in turn, a
 * round of its tour each, starting with the first, so that the next
 * visitor meets the first language again. An input during the tour
 * keeps the language then shown: the visitor was reading it. Pure: the
 * caller gives the times. */
#ifndef MK_LANG_H
#define MK_LANG_H

struct lang_pick {
	int count;  /* languages; 0 or 1: nothing to pick */
	int chosen; /* the visitor's, or the one the tour last showed */
};

void lang_pick_init(struct lang_pick *p, int count);

/* next-language pressed steps times (a press, or those since the last
 * call): the language chosen. */
int lang_pick_next(struct lang_pick *p, int steps);

/* The language shown idle seconds after the last input, attract mode
 * starting after attract_after seconds (0: never) and showing each
 * language for round seconds (one round of its tour; 0: the first
 * only). */
int lang_pick_shown(struct lang_pick *p, double idle, double attract_after, double round);

#endif
