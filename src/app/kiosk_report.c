#include "app/kiosk_report.h"
#include "app/kiosk_state.h"
#include "ops/screen.h"
#include "render/shading.h"
#include "scene/text/caption.h"
#include "util/clock.h"
#include "util/log.h"

/* What --status and the metrics say; last_error: the caller's buffer. */
static void report(const struct kiosk *k, struct status_report *r, char *last_error, size_t n)
{
	const struct app_state *st = app_state(k->app);

	log_last_error(last_error, n);
	*r = (struct status_report){
	    .model = k->content->model_path,
	    .matcap = k->content->set ? matcap_set_path(k->content->set, st->matcap) : NULL,
	    .mode = shading_mode_name(st->mode),
	    .view = {st->orientation.x, st->orientation.y, st->orientation.z, st->orientation.w},
	    .screen_on = !k->screen || screen_on(k->screen),
	    .camera_on = st->camera_on,
	    .uptime_s = (double)(monotonic_ns() - k->started_ns) / 1e9,
	    .frames_drawn = k->frames_drawn,
	    .last_error = last_error,
	    .last_error_at = log_last_error_time(),
	    .started_at = k->started_at,
	    .counts = k->counts,
	    .visits = &k->visits};
}

void kiosk_report_status(struct kiosk *k)
{
	struct image frame = {0};
	struct status_report r;
	char last_error[1024];
	bool have;

	if (!status_server_accept(k->status))
		return;
	report(k, &r, last_error, sizeof(last_error));
	/* While the live camera is the matcap the screen shows what it sees:
	 * no camera frame is ever written to a file, so no frame.png then. */
	have = k->frames_drawn > 0 && !app_state(k->app)->camera_on &&
	       status_server_wants_frame(k->status) &&
	       k->display->read_frame(k->display, &frame) == 0;
	/* On its plane the caption is not in the frame GL drew: put in. */
	if (have && k->caption_plane)
		caption_blend(content_caption(k->content, app_state(k->app)->stop),
			      k->caption_at[0], k->caption_at[1], &frame);
	status_server_answer(k->status, &r, have ? &frame : NULL);
	image_release(&frame);
}

void kiosk_report_metrics(struct kiosk *k, uint64_t now_ns, bool stopping)
{
	struct status_report r;
	char last_error[1024];

	if (!k->metrics || (!stopping && now_ns < metrics_deadline(k->metrics)))
		return;
	report(k, &r, last_error, sizeof(last_error));
	if (stopping)
		metrics_stop(k->metrics, &r);
	else
		metrics_update(k->metrics, &r, now_ns);
}
