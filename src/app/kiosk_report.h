/* What the live loop tells the outside about itself: --status's answer
 * (src/app/status.h) and the metrics file (src/app/metrics.h), from the
 * same report of its state. */
#ifndef MK_KIOSK_REPORT_H
#define MK_KIOSK_REPORT_H

#include <stdbool.h>
#include <stdint.h>

struct kiosk;

/* A --status client waits (the socket was readable): answer it, with
 * the frame on screen read back. */
void kiosk_report_status(struct kiosk *k);
/* The metrics file when it is due (the poll timeout brings the loop
 * here: nothing is done per frame); stopping: the last one, up 0. */
void kiosk_report_metrics(struct kiosk *k, uint64_t now_ns, bool stopping);

#endif
