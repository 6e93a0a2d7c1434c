#include "camera/camera_feed.h"
#include "util/clock.h"
#include "camera/camera.h"
#include "camera/camera_texture.h"
#include "util/log.h"

#include <poll.h>
#include <stdlib.h>
#include <time.h>

/* The matcap's side: a ball seen by the camera needs no more. */
#define MATCAP_SIZE 512

struct camera_feed {
	struct camera *cam;
	struct camera_texture *tex;
	bool present;	   /* the camera said it is there */
	bool broken;	   /* frames cannot be drawn: the journal said why */
	bool have_frame;   /* the texture holds a frame of this showing */
	bool have_seq;	   /* last_seq holds the last frame's sequence */
	unsigned last_seq; /* to count frames the camera made and we dropped */
	long shown, dropped;
	uint64_t pending_ns; /* completion time of the frame drawn, not yet on screen */
	struct camera_stats latency_ms, cpu_us[3]; /* by enum camera_path */
};

struct camera_feed *camera_feed_new(const struct camera_feed_config *c, const struct gl *gl,
				    const char *shader_dir, bool egl)
{
	struct camera_config cfg = {.id = c->id,
				    .width = c->width,
				    .height = c->height,
				    .stall_s = c->stall_s,
				    .log_level = log_get_level()};
	struct camera_feed *f;

	if (c->use == CAMERA_FEED_OFF)
		return NULL;
	if (!egl) {
		log_debug("camera: not with the osmesa backend (kms and egl-headless have it)");
		return NULL;
	}
	f = calloc(1, sizeof(*f));
	if (!f)
		return NULL;
	f->tex =
	    camera_texture_new(gl, shader_dir, MATCAP_SIZE, c->import == CAMERA_FEED_IMPORT_AUTO);
	f->cam = f->tex ? camera_new(&cfg) : NULL;
	if (!f->cam) {
		log_err("camera: cannot be set up; running without one");
		camera_feed_free(f);
		return NULL;
	}
	camera_texture_set_view(f->tex, &c->view);
	return f;
}

void camera_feed_free(struct camera_feed *f)
{
	if (!f)
		return;
	camera_free(f->cam);
	camera_texture_free(f->tex);
	free(f);
}

int camera_feed_fd(const struct camera_feed *f)
{
	return camera_fd(f->cam);
}

struct camera_feed_report camera_feed_service(struct camera_feed *f, short revents,
					      bool display_waiting, uint64_t now_ns)
{
	struct camera_feed_report r = {0};
	struct camera_state st;

	if (!f)
		return r;
	if (revents & POLLIN) {
		camera_dispatch(f->cam, &st);
		f->present = st.present;
		r.frame = st.frame;
	}
	if (f->pending_ns && !display_waiting) {
		camera_stats_add(&f->latency_ms, (double)(now_ns - f->pending_ns) * 1e-6);
		f->pending_ns = 0;
	}
	r.available = f->present && !f->broken;
	return r;
}

void camera_feed_stream(struct camera_feed *f, bool shown)
{
	if (f)
		camera_set_streaming(f->cam, shown && !f->broken);
}

static double thread_cpu_us(void)
{
	return (double)clock_ns(CLOCK_THREAD_CPUTIME_ID) / 1e3;
}

static void count_frame(struct camera_feed *f, const struct camera_frame *fr)
{
	if (f->have_seq && fr->sequence > f->last_seq)
		f->dropped += fr->sequence - f->last_seq - 1;
	f->have_seq = true;
	f->last_seq = fr->sequence;
	f->shown++;
	f->pending_ns = fr->completed_ns;
}

GLuint camera_feed_draw(struct camera_feed *f, bool shown)
{
	const struct camera_frame *fr;
	double t0;
	int ret;

	if (!f)
		return 0;
	/* Off (or lost): when it is on again, the image matcap stays until
	 * a new frame, rather than the last one from before. */
	if (!shown || f->broken) {
		f->have_frame = false;
		return 0;
	}
	fr = camera_take(f->cam);
	if (fr) {
		t0 = thread_cpu_us();
		ret = camera_texture_update(f->tex, fr);
		if (ret) {
			log_err("camera: its frames cannot be drawn; showing the image matcaps");
			f->broken = true;
			return 0;
		}
		camera_stats_add(&f->cpu_us[camera_texture_path(f->tex)], thread_cpu_us() - t0);
		count_frame(f, fr);
		f->have_frame = true;
	}
	return f->have_frame ? camera_texture_id(f->tex) : 0;
}

void camera_feed_print_stats(const struct camera_feed *f, FILE *out)
{
	if (!f)
		return;
	fprintf(out,
		"camera frames_shown %ld dropped %ld latency_median_ms %.2f latency_p90_ms %.2f",
		f->shown, f->dropped, camera_stats_percentile(&f->latency_ms, 0.5),
		camera_stats_percentile(&f->latency_ms, 0.9));
	for (int p = CAMERA_PATH_IMPORT; p <= CAMERA_PATH_UPLOAD; p++)
		if (f->cpu_us[p].n)
			fprintf(out, " %s_frames %d %s_cpu_median_us %.1f %s_cpu_p90_us %.1f",
				p == CAMERA_PATH_IMPORT ? "import" : "upload", f->cpu_us[p].n,
				p == CAMERA_PATH_IMPORT ? "import" : "upload",
				camera_stats_percentile(&f->cpu_us[p], 0.5),
				p == CAMERA_PATH_IMPORT ? "import" : "upload",
				camera_stats_percentile(&f->cpu_us[p], 0.9));
	fputc('\n', out);
	fflush(out);
}
