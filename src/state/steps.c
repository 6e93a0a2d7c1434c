#include "state/steps.h"

int app_variant_step(int shown, int count, int steps)
{
	int n = count + 1; /* every variant, and the default */
	int at;

	if (count <= 0)
		return -1;
	if (shown < -1 || shown >= count)
		shown = -1;
	at = ((shown + 1 + steps) % n + n) % n;
	return at - 1;
}

uint64_t steps_due(uint64_t *at, uint64_t now, uint64_t every)
{
	uint64_t n;

	if (!every || now < *at)
		return 0;
	n = (now - *at) / every + 1;
	*at += n * every;
	return n;
}

uint64_t steps_floor(uint64_t t, uint64_t period)
{
	return period ? t - t % period : t;
}
