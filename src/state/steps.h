/* Counting steps: a cycle's place after some presses (the variants in
 * turn), and a schedule's steps on its grid (attract mode's stops and
 * models, which kiosks on one shared clock must count alike). Pure. */
#ifndef MK_STEPS_H
#define MK_STEPS_H

#include <stdint.h>

/* The variant shown after `steps` next-variant presses from `shown`, of
 * a model of `count` variants: each in turn, then the file's default
 * materials (-1), then the first again. -1 for a model without any. */
int app_variant_step(int shown, int count, int steps);

/* A schedule due at *at and every `every` ns after: the steps due by
 * now (0 before *at), *at moved on to the first one after now. On the
 * grid of *at whatever the gap, so two kiosks that count from the same
 * time count the same steps however often they look. every 0: none. */
uint64_t steps_due(uint64_t *at, uint64_t now, uint64_t every);

/* The start of the period of length `period` that holds t, on the grid
 * of time 0 (the shared clock's epoch); t when period is 0. */
uint64_t steps_floor(uint64_t t, uint64_t period);

#endif
