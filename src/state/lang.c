/* The language shown (lang.h). */
#include "state/lang.h"

#include <math.h>

void lang_pick_init(struct lang_pick *p, int count)
{
	p->count = count > 0 ? count : 0;
	p->chosen = 0;
}

int lang_pick_next(struct lang_pick *p, int steps)
{
	if (p->count > 1)
		p->chosen = ((p->chosen + steps) % p->count + p->count) % p->count;
	return p->chosen;
}

int lang_pick_shown(struct lang_pick *p, double idle, double attract_after, double round)
{
	double rounds;

	if (p->count < 2)
		return 0;
	if (attract_after <= 0 || idle < attract_after)
		return p->chosen;
	rounds = round > 0 ? floor((idle - attract_after) / round) : 0;
	p->chosen = (int)fmod(rounds, p->count);
	return p->chosen;
}
