/* [status] metrics: what --status knows, written as a Prometheus text file
 * (exposition format 0.0.4) for node_exporter's textfile collector, every
 * few seconds from the live loop's poll timeout (no work on a frame), and
 * replaced whole each time (util/file.h), so the collector never reads
 * half a file. Names: the matcap_kiosk_ prefix, base units (seconds),
 * _total for counters, _info for a gauge of 1 whose labels are the value. */
#ifndef MK_METRICS_H
#define MK_METRICS_H

#include "ops/status.h"

#include <stdint.h>
#include <stdio.h>

/* How often the file is written. */
#define METRICS_EVERY_NS 5000000000ull

/* The text of the file: every metric of r (up 1, or 0 when !up), with
 * version in matcap_kiosk_build_info. */
void metrics_write(FILE *f, const struct status_report *r, const char *version, bool up);

/* A label value as the exposition format wants it: backslash, double
 * quote and line feed escaped; bytes that are not UTF-8 (a file name may
 * have them) become U+FFFD, which the collector's parser would refuse. */
void metrics_write_label(FILE *f, const char *value);

struct metrics;

/* Writing to path (copied); NULL when path is NULL or empty (no metrics),
 * or out of memory. Due at once. */
struct metrics *metrics_new(const char *path);
/* Leaves the file as it is (metrics_stop writes the last one). */
void metrics_free(struct metrics *m);
/* *m made to write path (NULL or "": none) if it writes another file:
 * that one removed, as one left behind would say up 1 forever. At the
 * start and after a reload. */
void metrics_follow(struct metrics **m, const char *path);
/* When the file is due; CLOCK_NEVER for NULL. */
uint64_t metrics_deadline(const struct metrics *m);
/* The file written (or the failure logged, once until it works again);
 * the next one due METRICS_EVERY_NS later. */
void metrics_update(struct metrics *m, const struct status_report *r, uint64_t now_ns);
/* The kiosk stops: the last file, with matcap_kiosk_up 0. */
void metrics_stop(struct metrics *m, const struct status_report *r);

#endif
