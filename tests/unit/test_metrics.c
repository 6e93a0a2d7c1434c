/* [status] metrics: the Prometheus text file, line for line (names, types,
 * units, labels); label values escaped as the exposition format says
 * (backslash, double quote, line feed) and bytes that are not UTF-8
 * replaced; the file replaced whole, readable by another user, written
 * when due and not before, up 0 at the stop, removed when the settings
 * name another; a folder that is not there logged once. The live file as
 * node_exporter reads it: tests/e2e/metrics.sh. */
#include "ops/metrics.h"
#include "util/clock.h"
#include "util/log.h"

#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[64];

static int dir_setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/mk-metrics-XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	log_set_level(LOG_ERR);
	return 0;
}

static int dir_teardown(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static const struct status_report sample = {
    .model = "/srv/matcap-kiosk/chair.glb",
    .matcap = "/usr/share/matcap-kiosk/matcaps/gold.png",
    .mode = "view",
    .screen_on = true,
    .camera_on = false,
    .uptime_s = 12.5,
    .frames_drawn = 1234,
    .last_error = "",
    .last_error_at = 0,
    .started_at = 1700000000.25,
    .counts = {.reloads = 3, .reload_failures = 1, .model_loads = 7, .model_load_failures = 2},
};

/* metrics_write's text, malloc'd. */
static char *text_of(const struct status_report *r, bool up)
{
	char *buf = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&buf, &size);

	assert_non_null(f);
	metrics_write(f, r, "1.2.3", up);
	assert_int_equal(fclose(f), 0);
	return buf;
}

static char *label_of(const char *value)
{
	char *buf = NULL;
	size_t size = 0;
	FILE *f = open_memstream(&buf, &size);

	assert_non_null(f);
	metrics_write_label(f, value);
	assert_int_equal(fclose(f), 0);
	return buf;
}

/* Whether text has line as one whole line. */
static bool has_line(const char *text, const char *line)
{
	size_t n = strlen(line);

	for (const char *p = text; (p = strstr(p, line)); p++)
		if ((p == text || p[-1] == '\n') && p[n] == '\n')
			return true;
	return false;
}

static void test_content(void **state)
{
	char *t = text_of(&sample, true);
	static const char *const lines[] = {
	    "# TYPE matcap_kiosk_up gauge",
	    "matcap_kiosk_up 1",
	    "# TYPE matcap_kiosk_build_info gauge",
	    "matcap_kiosk_build_info{version=\"1.2.3\"} 1",
	    "# TYPE matcap_kiosk_start_time_seconds gauge",
	    "matcap_kiosk_start_time_seconds 1700000000.250",
	    "matcap_kiosk_uptime_seconds 12.500",
	    "# TYPE matcap_kiosk_frames_drawn_total counter",
	    "matcap_kiosk_frames_drawn_total 1234",
	    "# TYPE matcap_kiosk_shown_info gauge",
	    "matcap_kiosk_shown_info{model=\"/srv/matcap-kiosk/chair.glb\","
	    "matcap=\"/usr/share/matcap-kiosk/matcaps/gold.png\",mode=\"view\"} 1",
	    "matcap_kiosk_screen_on 1",
	    "matcap_kiosk_camera_on 0",
	    "# TYPE matcap_kiosk_last_error_timestamp_seconds gauge",
	    "matcap_kiosk_last_error_timestamp_seconds 0.000",
	    "# TYPE matcap_kiosk_reloads_total counter",
	    "matcap_kiosk_reloads_total{result=\"done\"} 3",
	    "matcap_kiosk_reloads_total{result=\"failed\"} 1",
	    "# TYPE matcap_kiosk_model_loads_total counter",
	    "matcap_kiosk_model_loads_total{result=\"shown\"} 7",
	    "matcap_kiosk_model_loads_total{result=\"failed\"} 2",
	};
	int samples = 0, helps = 0, types = 0;

	(void)state;
	for (size_t i = 0; i < sizeof(lines) / sizeof(lines[0]); i++)
		if (!has_line(t, lines[i]))
			fail_msg("missing line: %s\nin:\n%s", lines[i], t);
	/* No error yet: no _info line for one. */
	assert_null(strstr(t, "last_error_info"));
	/* Every metric has its HELP and TYPE, and every line is one of the
	 * three kinds, under the prefix. */
	for (char *line = strtok(t, "\n"); line; line = strtok(NULL, "\n")) {
		if (!strncmp(line, "# HELP matcap_kiosk_", 20))
			helps++;
		else if (!strncmp(line, "# TYPE matcap_kiosk_", 20))
			types++;
		else if (!strncmp(line, "matcap_kiosk_", 13))
			samples++;
		else
			fail_msg("a line of another kind: %s", line);
	}
	assert_int_equal(helps, 11);
	assert_int_equal(types, 11);
	assert_int_equal(samples, 13);
	free(t);
}

static void test_down_and_builtin(void **state)
{
	struct status_report r = sample;
	char *t;

	(void)state;
	r.model = r.matcap = NULL;
	r.screen_on = false;
	r.last_error = "cannot read /srv/x.glb";
	r.last_error_at = 1700000100.5;
	t = text_of(&r, false);
	assert_true(has_line(t, "matcap_kiosk_up 0"));
	assert_true(has_line(t, "matcap_kiosk_screen_on 0"));
	assert_true(has_line(t, "matcap_kiosk_shown_info{model=\"built-in\",matcap=\"built-in\","
				"mode=\"view\"} 1"));
	assert_true(has_line(t, "matcap_kiosk_last_error_timestamp_seconds 1700000100.500"));
	assert_true(has_line(t, "# TYPE matcap_kiosk_last_error_info gauge"));
	assert_true(
	    has_line(t, "matcap_kiosk_last_error_info{error=\"cannot read /srv/x.glb\"} 1"));
	free(t);
}

/* What visitors did: presses by source and action, visits, seconds per
 * slot (a hotspot's name escaped like any label); none of it without
 * visits in the report. */
static void test_visits(void **state)
{
	struct status_report r = sample;
	struct visits v = {0};
	struct app_event ev = {
	    .time_ns = 1000000000ull, .action = ACTION_TURN_RIGHT, .pressed = true};
	struct gesture tap = {.kind = GESTURE_TAP, .time_ns = 2000000000ull};
	static const char *const lines[] = {
	    "# TYPE matcap_kiosk_presses_total counter",
	    "matcap_kiosk_presses_total{source=\"knob\",action=\"turn-right\"} 2",
	    "matcap_kiosk_presses_total{source=\"touch\",action=\"tap\"} 1",
	    "# TYPE matcap_kiosk_visits_total counter",
	    "matcap_kiosk_visits_total 1",
	    "# TYPE matcap_kiosk_shown_seconds_total counter",
	    "matcap_kiosk_shown_seconds_total{kind=\"stop\",name=\"2\"} 4.500",
	    "matcap_kiosk_shown_seconds_total{kind=\"hotspot\",name=\"the \\\"valve\\\"\"} 1.250",
	};
	char *t = text_of(&r, true);

	(void)state;
	assert_null(strstr(t, "presses_total"));
	free(t);
	visits_press(&v, INPUT_KIND_KNOB, &ev, 30);
	visits_press(&v, INPUT_KIND_KNOB, &ev, 30);
	visits_touch(&v, &tap, ACTION_NONE, 30);
	visit_time_add(&v, "stop", "2", 4.5);
	visit_time_add(&v, "hotspot", "the \"valve\"", 1.25);
	r.visits = &v;
	t = text_of(&r, true);
	for (size_t i = 0; i < sizeof(lines) / sizeof(lines[0]); i++)
		if (!has_line(t, lines[i]))
			fail_msg("missing line: %s\n--- got:\n%s", lines[i], t);
	free(t);
}

static void test_escaping(void **state)
{
	static const struct {
		const char *in, *out;
	} cases[] = {
	    {"plain/path.glb", "plain/path.glb"},
	    {"a\\b", "a\\\\b"},
	    {"say \"hi\"", "say \\\"hi\\\""},
	    {"two\nlines", "two\\nlines"},
	    {"tab\tstays", "tab\tstays"},
	    {"caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80",
	     "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80"},
	    {"latin1 \xe9!", "latin1 \xef\xbf\xbd!"},
	    {"cut \xe2\x82", "cut \xef\xbf\xbd\xef\xbf\xbd"},
	    {"overlong \xc0\xaf", "overlong \xef\xbf\xbd\xef\xbf\xbd"},
	    {"surrogate \xed\xa0\x80", "surrogate \xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd"},
	    {"", ""},
	};

	(void)state;
	for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		char *got = label_of(cases[i].in);

		assert_string_equal(got, cases[i].out);
		free(got);
	}
}

static void test_escaped_in_file(void **state)
{
	struct status_report r = sample;
	char *t;

	(void)state;
	r.model = "/srv/a \"quoted\" \\ name.glb";
	r.last_error = "/srv/x.glb:3: expected \"}\"\nnext";
	t = text_of(&r, true);
	assert_true(has_line(t, "matcap_kiosk_shown_info{model=\"/srv/a \\\"quoted\\\" \\\\ "
				"name.glb\",matcap=\"/usr/share/matcap-kiosk/matcaps/gold.png\","
				"mode=\"view\"} 1"));
	assert_true(has_line(t, "matcap_kiosk_last_error_info{error=\"/srv/x.glb:3: expected "
				"\\\"}\\\"\\nnext\"} 1"));
	free(t);
}

static char *read_text(const char *path)
{
	FILE *f = fopen(path, "r");
	char *buf;
	long n;

	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	n = ftell(f);
	rewind(f);
	buf = calloc(1, (size_t)n + 1);
	assert_int_equal(fread(buf, 1, (size_t)n, f), (size_t)n);
	fclose(f);
	return buf;
}

/* Files in dir other than the one named: the temporary ones left behind. */
static int others_in_dir(const char *name)
{
	DIR *d = opendir(dir);
	struct dirent *e;
	int n = 0;

	assert_non_null(d);
	while ((e = readdir(d)))
		n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && strcmp(e->d_name, name);
	closedir(d);
	return n;
}

static void test_file(void **state)
{
	struct status_report r = sample;
	struct metrics *m = NULL;
	char path[128], moved[128];
	struct stat st;
	mode_t old = umask(077); /* the service's UMask */
	char *t;

	(void)state;
	snprintf(path, sizeof(path), "%s/kiosk.prom", dir);
	snprintf(moved, sizeof(moved), "%s/other.prom", dir);
	metrics_follow(&m, NULL);
	assert_null(m);
	assert_int_equal(metrics_deadline(m), CLOCK_NEVER);
	metrics_follow(&m, path);
	assert_non_null(m);
	/* Due at once, then METRICS_EVERY_NS later. */
	assert_int_equal(metrics_deadline(m), 0);
	metrics_update(m, &r, 1000);
	assert_int_equal(metrics_deadline(m), 1000 + METRICS_EVERY_NS);
	assert_int_equal(stat(path, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0644);
	assert_int_equal(others_in_dir("kiosk.prom"), 0);
	t = read_text(path);
	assert_non_null(t);
	assert_true(has_line(t, "matcap_kiosk_up 1"));
	assert_true(has_line(t, "matcap_kiosk_frames_drawn_total 1234"));
	free(t);
	/* The same path again changes nothing; the stop says up 0. */
	metrics_follow(&m, path);
	assert_int_equal(metrics_deadline(m), 1000 + METRICS_EVERY_NS);
	r.frames_drawn = 1300;
	metrics_stop(m, &r);
	t = read_text(path);
	assert_true(has_line(t, "matcap_kiosk_up 0"));
	assert_true(has_line(t, "matcap_kiosk_frames_drawn_total 1300"));
	free(t);
	/* Another path: the old file goes, the new one is due at once. */
	metrics_follow(&m, moved);
	assert_int_equal(access(path, F_OK), -1);
	assert_int_equal(metrics_deadline(m), 0);
	metrics_update(m, &r, 5);
	assert_int_equal(access(moved, R_OK), 0);
	metrics_follow(&m, "");
	assert_null(m);
	assert_int_equal(access(moved, F_OK), -1);
	umask(old);
}

static void test_no_folder(void **state)
{
	struct metrics *m = metrics_new("/nonexistent-mk-folder/kiosk.prom");
	char err[1024];

	(void)state;
	assert_non_null(m);
	metrics_update(m, &sample, 0);
	log_last_error(err, sizeof(err));
	assert_non_null(strstr(err, "metrics: cannot write /nonexistent-mk-folder/kiosk.prom"));
	assert_true(log_last_error_time() > 1.6e9);
	/* Still due again later: a folder made meanwhile is written. */
	assert_int_equal(metrics_deadline(m), METRICS_EVERY_NS);
	metrics_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_content),  cmocka_unit_test(test_down_and_builtin),
	    cmocka_unit_test(test_escaping), cmocka_unit_test(test_escaped_in_file),
	    cmocka_unit_test(test_file),     cmocka_unit_test(test_no_folder),
	    cmocka_unit_test(test_visits),
	};

	return cmocka_run_group_tests(tests, dir_setup, dir_teardown);
}
