#include "ops/metrics.h"
#include "util/clock.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef MK_VERSION
#define MK_VERSION "0.0.0"
#endif

struct metrics {
	char *path;
	uint64_t due_ns;
	int failed; /* the last write's error, logged once; 0: it worked */
};

/* The length of the UTF-8 sequence at s (1 to 4), or 0 when it is not one
 * (overlong forms, surrogates and past U+10FFFF included). */
static int utf8_length(const unsigned char *s)
{
	int n = s[0] < 0x80		       ? 1
		: s[0] >= 0xc2 && s[0] <= 0xdf ? 2
		: (s[0] & 0xf0) == 0xe0	       ? 3
		: s[0] >= 0xf0 && s[0] <= 0xf4 ? 4
					       : 0;

	for (int i = 1; i < n; i++)
		if ((s[i] & 0xc0) != 0x80)
			return 0;
	if ((n == 3 && s[0] == 0xe0 && s[1] < 0xa0) || (n == 3 && s[0] == 0xed && s[1] >= 0xa0) ||
	    (n == 4 && s[0] == 0xf0 && s[1] < 0x90) || (n == 4 && s[0] == 0xf4 && s[1] >= 0x90))
		return 0;
	return n;
}

void metrics_write_label(FILE *f, const char *value)
{
	const unsigned char *s = (const unsigned char *)value;

	while (*s) {
		int n = utf8_length(s);

		if (*s == '\\' || *s == '"')
			fprintf(f, "\\%c", *s);
		else if (*s == '\n')
			fputs("\\n", f);
		else if (n)
			fwrite(s, 1, (size_t)n, f);
		else
			fputs("\xef\xbf\xbd", f);
		s += n ? n : 1;
	}
}

/* One metric's HELP and TYPE lines. */
static void head(FILE *f, const char *name, const char *type, const char *help)
{
	fprintf(f, "# HELP matcap_kiosk_%s %s\n# TYPE matcap_kiosk_%s %s\n", name, help, name,
		type);
}

static void label(FILE *f, const char *name, const char *value, const char *next)
{
	fprintf(f, "%s=\"", name);
	metrics_write_label(f, value);
	fprintf(f, "\"%s", next);
}

static void counter_pair(FILE *f, const char *name, const char *help, const char *ok, long oks,
			 const char *bad, long bads)
{
	head(f, name, "counter", help);
	fprintf(f, "matcap_kiosk_%s{result=\"%s\"} %ld\n", name, ok, oks);
	fprintf(f, "matcap_kiosk_%s{result=\"%s\"} %ld\n", name, bad, bads);
}

static void shown(FILE *f, const struct status_report *r)
{
	head(f, "shown_info", "gauge",
	     "What is on screen: the model and matcap files (built-in: the knot, the clay) and the "
	     "shading mode.");
	fputs("matcap_kiosk_shown_info{", f);
	label(f, "model", r->model ? r->model : "built-in", ",");
	label(f, "matcap", r->matcap ? r->matcap : "built-in", ",");
	label(f, "mode", r->mode ? r->mode : "", "} 1\n");
}

static void last_error(FILE *f, const struct status_report *r)
{
	head(f, "last_error_timestamp_seconds", "gauge",
	     "When the last error was logged, in seconds since the epoch; 0: none (since the "
	     "start, or the last reload that went well).");
	fprintf(f, "matcap_kiosk_last_error_timestamp_seconds %.3f\n", r->last_error_at);
	if (!r->last_error || !*r->last_error)
		return;
	head(f, "last_error_info", "gauge", "The last error logged, as the journal has it.");
	fputs("matcap_kiosk_last_error_info{", f);
	label(f, "error", r->last_error, "} 1\n");
}

/* What visitors did (state/visits.h): kept on the kiosk, said here only. */
static void visits(FILE *f, const struct visits *v)
{
	head(f, "presses_total", "counter",
	     "Presses by the visitors, per source (button, key, touch, knob) and action (a "
	     "touch's drag, pinch and tap beside the actions).");
	for (int s = 0; s < INPUT_KINDS; s++)
		for (int a = 1; a < VISITS_ACTIONS; a++)
			if (v->presses[s][a])
				fprintf(
				    f,
				    "matcap_kiosk_presses_total{source=\"%s\",action=\"%s\"} %ld\n",
				    input_kind_names[s], visits_action_name(a), v->presses[s][a]);
	head(f, "visits_total", "counter",
	     "Visits: an input after the kiosk was idle (attract mode, or no input for "
	     "attract_after).");
	fprintf(f, "matcap_kiosk_visits_total %ld\n", v->count);
	head(f, "shown_seconds_total", "counter",
	     "Seconds shown to the visitors: at each stop (kind stop, name its number from 1), in "
	     "attract mode (kind attract), and what hotspots and languages count.");
	for (int i = 0; i < v->slot_count; i++) {
		fputs("matcap_kiosk_shown_seconds_total{", f);
		label(f, "kind", v->slots[i].kind, ",");
		label(f, "name", v->slots[i].name, "} ");
		fprintf(f, "%.3f\n", v->slots[i].seconds);
	}
}

void metrics_write(FILE *f, const struct status_report *r, const char *version, bool up)
{
	head(f, "up", "gauge",
	     "1 while the kiosk runs, 0 once it stopped cleanly (a file that stops changing: see "
	     "node_textfile_mtime_seconds).");
	fprintf(f, "matcap_kiosk_up %d\n", up);
	head(f, "build_info", "gauge", "The kiosk's version.");
	fputs("matcap_kiosk_build_info{", f);
	label(f, "version", version, "} 1\n");
	head(f, "start_time_seconds", "gauge",
	     "When the kiosk started, in seconds since the epoch.");
	fprintf(f, "matcap_kiosk_start_time_seconds %.3f\n", r->started_at);
	head(f, "uptime_seconds", "gauge", "How long the kiosk has run.");
	fprintf(f, "matcap_kiosk_uptime_seconds %.3f\n", r->uptime_s);
	head(f, "frames_drawn_total", "counter", "Frames drawn since the start.");
	fprintf(f, "matcap_kiosk_frames_drawn_total %ld\n", r->frames_drawn);
	shown(f, r);
	head(f, "screen_on", "gauge", "1 while the screen is on, 0 while it sleeps ([power]).");
	fprintf(f, "matcap_kiosk_screen_on %d\n", r->screen_on);
	head(f, "camera_on", "gauge", "1 while a live camera is the matcap.");
	fprintf(f, "matcap_kiosk_camera_on %d\n", r->camera_on);
	last_error(f, r);
	counter_pair(f, "reloads_total",
		     "Reloads (SIGHUP): done, or failed and the scene on screen kept.", "done",
		     r->counts.reloads, "failed", r->counts.reload_failures);
	counter_pair(f, "model_loads_total",
		     "Models of the folder or list loaded while running: shown, or failed.",
		     "shown", r->counts.model_loads, "failed", r->counts.model_load_failures);
	if (r->visits)
		visits(f, r->visits);
}

struct metrics *metrics_new(const char *path)
{
	struct metrics *m;

	if (!path || !*path)
		return NULL;
	m = calloc(1, sizeof(*m));
	if (m && !(m->path = strdup(path))) {
		free(m);
		m = NULL;
	}
	if (m)
		log_info("metrics: writing %s every %llu s", path,
			 (unsigned long long)(METRICS_EVERY_NS / 1000000000ull));
	return m;
}

void metrics_free(struct metrics *m)
{
	if (!m)
		return;
	free(m->path);
	free(m);
}

void metrics_follow(struct metrics **m, const char *path)
{
	bool none = !path || !*path;

	if (*m ? !none && strcmp((*m)->path, path) == 0 : none)
		return;
	if (*m) {
		log_info("metrics: no longer written to %s: removed", (*m)->path);
		unlink((*m)->path);
	}
	metrics_free(*m);
	*m = metrics_new(path);
}

uint64_t metrics_deadline(const struct metrics *m)
{
	return m ? m->due_ns : CLOCK_NEVER;
}

/* Readable by node_exporter's user: the service's UMask=0077 does not
 * apply (file_atomic_begin sets the mode). */
static int write_file(const char *path, const struct status_report *r, bool up)
{
	struct file_atomic a;
	FILE *f;
	int ret = file_atomic_begin(&a, path, 0644);

	if (ret)
		return ret;
	f = fdopen(dup(a.fd), "w");
	if (!f)
		return file_atomic_end(&a, -errno, false);
	metrics_write(f, r, MK_VERSION, up);
	ret = ferror(f) ? -EIO : 0;
	if (fclose(f) && !ret)
		ret = -errno;
	return file_atomic_end(&a, ret, false);
}

static void update(struct metrics *m, const struct status_report *r, bool up)
{
	int ret = write_file(m->path, r, up);

	if (ret && ret != m->failed)
		log_err("metrics: cannot write %s: %s (expected a file in a folder the kiosk may "
			"write, e.g. /var/lib/matcap-kiosk/matcap-kiosk.prom)",
			m->path, strerror(-ret));
	else if (!ret && m->failed)
		log_info("metrics: writing %s again", m->path);
	m->failed = ret;
}

void metrics_update(struct metrics *m, const struct status_report *r, uint64_t now_ns)
{
	if (!m)
		return;
	update(m, r, true);
	m->due_ns = now_ns + METRICS_EVERY_NS;
}

void metrics_stop(struct metrics *m, const struct status_report *r)
{
	if (m)
		update(m, r, false);
}
