/* --status's socket: a client is answered with the state as JSON (strings
 * escaped), the same text lands in state.json, a second kiosk does not
 * take a running one's socket, a dead one's is taken over, and the client
 * fails with a clear line when nobody answers. */
#include "ops/status.h"
#include "util/log.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <cmocka.h>

static char dir[64];

static int dir_setup(void **state)
{
	(void)state;
	snprintf(dir, sizeof(dir), "/tmp/mk-status-XXXXXX");
	if (!mkdtemp(dir))
		return -1;
	setenv("RUNTIME_DIRECTORY", dir, 1);
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

static int connect_socket(void)
{
	struct sockaddr_un a = {.sun_family = AF_UNIX};
	int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);

	snprintf(a.sun_path, sizeof(a.sun_path), "%s/status.sock", dir);
	if (fd >= 0 && connect(fd, (struct sockaddr *)&a, sizeof(a)) == 0)
		return fd;
	if (fd >= 0)
		close(fd);
	return -1;
}

static void read_all(int fd, char *buf, size_t n)
{
	size_t got = 0;
	ssize_t r;

	while (got + 1 < n && (r = read(fd, buf + got, n - got - 1)) > 0)
		got += (size_t)r;
	buf[got] = '\0';
}

static void test_answer(void **state)
{
	struct status_server *s = status_server_new();
	struct status_report r = {.model = "/srv/a \"b\".glb",
				  .mode = "normal",
				  .view = {0, 0, 0, 1},
				  .screen_on = false,
				  .uptime_s = 12.5,
				  .frames_drawn = 42,
				  .last_error = "line\none"};
	struct visits v = {.count = 3};
	char buf[4096], path[128], file[4096];
	FILE *f;
	int fd;

	(void)state;
	assert_non_null(s);
	assert_true(status_server_fd(s) >= 0);
	assert_false(status_server_accept(s)); /* nobody asked yet */
	fd = connect_socket();
	assert_true(fd >= 0);
	assert_true(status_server_accept(s));
	/* What visitors did, as the metrics say it. */
	v.presses[INPUT_KIND_KNOB][ACTION_SELECT] = 2;
	visit_time_add(&v, "stop", "1", 12.25);
	r.visits = &v;
	status_server_answer(s, &r, NULL);
	read_all(fd, buf, sizeof(buf));
	close(fd);
	assert_non_null(strstr(buf,
			       "\"visits\": {\"count\": 3, \"presses\": [{\"source\": \"knob\", "
			       "\"action\": \"select\", \"count\": 2}], \"seconds\": [{\"kind\": "
			       "\"stop\", \"name\": \"1\", \"seconds\": 12.250}]}"));
	assert_non_null(strstr(buf, "\"model\": \"/srv/a \\\"b\\\".glb\""));
	assert_non_null(strstr(buf, "\"matcap\": null"));
	assert_non_null(strstr(buf, "\"power\": \"off\""));
	assert_non_null(strstr(buf, "\"frames_drawn\": 42"));
	assert_non_null(strstr(buf, "\"last_error\": \"line\\u000aone\""));
	assert_non_null(strstr(buf, "\"frame\": null"));
	snprintf(path, sizeof(path), "%s/state.json", dir);
	f = fopen(path, "r");
	assert_non_null(f);
	file[fread(file, 1, sizeof(file) - 1, f)] = '\0';
	fclose(f);
	assert_string_equal(file, buf);
	status_server_free(s);
	snprintf(path, sizeof(path), "%s/status.sock", dir);
	assert_int_equal(access(path, F_OK), -1); /* removed at the end */
}

static void test_frame(void **state)
{
	struct status_server *s = status_server_new();
	struct status_report r = {.mode = "view", .last_error = ""};
	struct image img = {0};
	struct stat st;
	char buf[4096], path[128];
	int fd;

	(void)state;
	assert_int_equal(image_alloc(&img, 4, 3), 0);
	fd = connect_socket();
	assert_true(fd >= 0 && status_server_accept(s));
	status_server_answer(s, &r, &img);
	/* The pixels are the writer thread's: the loop keeps none. */
	assert_null(img.rgba);
	assert_int_equal(img.width, 0);
	read_all(fd, buf, sizeof(buf));
	close(fd);
	snprintf(path, sizeof(path), "%s/frame.png", dir);
	assert_int_equal(stat(path, &st), 0);
	assert_true(st.st_size > 0);
	assert_int_equal(st.st_mode & 0777, 0600); /* a shop's screen: ours alone */
	assert_non_null(strstr(buf, path));
	snprintf(path, sizeof(path), "%s/status.sock", dir);
	assert_int_equal(stat(path, &st), 0);
	assert_int_equal(st.st_mode & 0777, 0600);
	/* Asked again within a second: no frame read back, the last one named. */
	assert_false(status_server_wants_frame(s));
	fd = connect_socket();
	assert_true(fd >= 0 && status_server_accept(s));
	status_server_answer(s, &r, NULL);
	read_all(fd, buf, sizeof(buf));
	close(fd);
	assert_non_null(strstr(buf, "frame.png"));
	image_release(&img);
	status_server_free(s);
}

/* A running kiosk keeps its socket; a dead one's is taken over. */
static void test_one_kiosk(void **state)
{
	struct status_server *a = status_server_new(), *b = status_server_new();
	struct sockaddr_un addr = {.sun_family = AF_UNIX};
	int stale;

	(void)state;
	assert_non_null(a);
	assert_null(b);
	status_server_free(a);
	snprintf(addr.sun_path, sizeof(addr.sun_path), "%s/status.sock", dir);
	stale = socket(AF_UNIX, SOCK_STREAM, 0);
	assert_int_equal(bind(stale, (struct sockaddr *)&addr, sizeof(addr)), 0);
	close(stale); /* bound, never listening: what a killed kiosk leaves */
	b = status_server_new();
	assert_non_null(b);
	status_server_free(b);
}

static void test_no_kiosk(void **state)
{
	FILE *out = tmpfile();

	(void)state;
	assert_int_equal(status_client_run(out), 1);
	assert_int_equal(ftell(out), 0);
	fclose(out);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_answer),
	    cmocka_unit_test(test_frame),
	    cmocka_unit_test(test_one_kiosk),
	    cmocka_unit_test(test_no_kiosk),
	};

	return cmocka_run_group_tests(tests, dir_setup, dir_teardown);
}
