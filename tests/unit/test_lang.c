/* Which language is shown (state/lang.c): the visitor's next-language
 * steps through them and wraps; after idle_seconds attract mode shows
 * the first, then each in turn, a round of its tour each; an input
 * during the tour keeps the language the visitor was reading; a single
 * language or none is always the first. */
#include "state/lang.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* idle_seconds 60, a round of the tour 30 s. */
#define AFTER 60
#define ROUND 30

static void visitor_steps(void **state)
{
	struct lang_pick p;

	(void)state;
	lang_pick_init(&p, 3);
	assert_int_equal(lang_pick_shown(&p, 0, AFTER, ROUND), 0);
	assert_int_equal(lang_pick_next(&p, 1), 1);
	assert_int_equal(lang_pick_shown(&p, 5, AFTER, ROUND), 1);
	assert_int_equal(lang_pick_next(&p, 1), 2);
	assert_int_equal(lang_pick_next(&p, 1), 0); /* wraps */
	assert_int_equal(lang_pick_next(&p, 5), 2); /* presses counted together */
	assert_int_equal(lang_pick_next(&p, -1), 1);
	/* Still chosen just before attract mode. */
	assert_int_equal(lang_pick_shown(&p, AFTER - 0.001, AFTER, ROUND), 1);
}

static void the_first_comes_back(void **state)
{
	struct lang_pick p;

	(void)state;
	lang_pick_init(&p, 3);
	lang_pick_next(&p, 2);
	/* idle_seconds after the last input: the first, for a round. */
	assert_int_equal(lang_pick_shown(&p, AFTER, AFTER, ROUND), 0);
	assert_int_equal(lang_pick_shown(&p, AFTER + ROUND - 1, AFTER, ROUND), 0);
	/* Then each in turn, a round each, and round again. */
	assert_int_equal(lang_pick_shown(&p, AFTER + ROUND, AFTER, ROUND), 1);
	assert_int_equal(lang_pick_shown(&p, AFTER + 2 * ROUND + 1, AFTER, ROUND), 2);
	assert_int_equal(lang_pick_shown(&p, AFTER + 3 * ROUND, AFTER, ROUND), 0);
	assert_int_equal(lang_pick_shown(&p, AFTER + 4 * ROUND, AFTER, ROUND), 1);
	/* An input now (idle back to 0): the one being read stays. */
	assert_int_equal(lang_pick_shown(&p, 0, AFTER, ROUND), 1);
	/* And next-language goes on from it. */
	assert_int_equal(lang_pick_next(&p, 1), 2);
}

static void without_a_tour(void **state)
{
	struct lang_pick p;

	(void)state;
	lang_pick_init(&p, 2);
	lang_pick_next(&p, 1);
	/* No attract mode (idle_seconds 0): the visitor's stays. */
	assert_int_equal(lang_pick_shown(&p, 1e6, 0, ROUND), 1);
	/* A tour without rounds: the first, once idle. */
	assert_int_equal(lang_pick_shown(&p, AFTER, AFTER, 0), 0);
	/* One language, or none: the first, whatever is pressed. */
	lang_pick_init(&p, 1);
	assert_int_equal(lang_pick_next(&p, 1), 0);
	assert_int_equal(lang_pick_shown(&p, AFTER + 5 * ROUND, AFTER, ROUND), 0);
	lang_pick_init(&p, 0);
	assert_int_equal(lang_pick_next(&p, 3), 0);
	assert_int_equal(lang_pick_shown(&p, 0, AFTER, ROUND), 0);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(visitor_steps),
	    cmocka_unit_test(the_first_comes_back),
	    cmocka_unit_test(without_a_tour),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
