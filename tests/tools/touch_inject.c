/* A touchscreen for the virtual board (tests/e2e/touch.sh): a uinput
 * device, "touch-inject touchscreen", type-B multitouch (ABS_MT_SLOT,
 * TRACKING_ID, POSITION_X/Y, INPUT_PROP_DIRECT; with BTN_TOUCH and ABS_X/Y
 * as real panels send them), axes 0..4000 so that test fractions are
 * exact. With -s it is a single-touch panel (BTN_TOUCH, ABS_X/Y) instead.
 *
 *   touch_inject [-s] FIFO
 *
 * reads lines from FIFO and touches:
 *   drag X0 Y0 X1 Y1 STEPS MS    one finger down, STEPS moves MS apart, up
 *   pinch CX CY D0 D1 STEPS MS   two fingers CX +- D/2, from D0 to D1 apart
 *   tap X Y                      down, 40 ms, up
 *   doubletap X Y                two taps 120 ms apart
 *   hold X Y MS                  down, MS still, up
 *   quit
 * and after each prints "done WHAT" on stdout. */
#include <errno.h>
#include <fcntl.h>
#include <linux/uinput.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define AXIS_MAX 4000

struct panel {
	int fd;
	bool single;
	int next_id;
};

static void sleep_ms(long ms)
{
	struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};

	while (nanosleep(&ts, &ts) && errno == EINTR)
		;
}

static void emit(const struct panel *p, int type, int code, int value)
{
	struct input_event ev = {
	    .type = (unsigned short)type, .code = (unsigned short)code, .value = value};

	if (write(p->fd, &ev, sizeof(ev)) != (ssize_t)sizeof(ev))
		fprintf(stderr, "touch_inject: write: %s\n", strerror(errno));
}

/* Fingers: n of them at x[i], y[i] (n 0: all lifted), where was were down
 * before; a finger that comes down gets a new tracking id. */
static void frame(struct panel *p, int n, const int *x, const int *y, int was)
{
	if (!p->single) {
		for (int i = 0; i < 2; i++) {
			if (i >= n && i >= was)
				continue;
			emit(p, EV_ABS, ABS_MT_SLOT, i);
			if (i >= n) {
				emit(p, EV_ABS, ABS_MT_TRACKING_ID, -1);
				continue;
			}
			if (i >= was)
				emit(p, EV_ABS, ABS_MT_TRACKING_ID, p->next_id++);
			emit(p, EV_ABS, ABS_MT_POSITION_X, x[i]);
			emit(p, EV_ABS, ABS_MT_POSITION_Y, y[i]);
		}
	}
	if (n > 0) {
		emit(p, EV_ABS, ABS_X, x[0]);
		emit(p, EV_ABS, ABS_Y, y[0]);
	}
	if ((n > 0) != (was > 0))
		emit(p, EV_KEY, BTN_TOUCH, n > 0);
	emit(p, EV_SYN, SYN_REPORT, 0);
}

static void drag(struct panel *p, int x0, int y0, int x1, int y1, int steps, int ms)
{
	int x = x0, y = y0;

	frame(p, 1, &x, &y, 0);
	for (int i = 1; i <= steps; i++) {
		sleep_ms(ms);
		x = x0 + (x1 - x0) * i / steps;
		y = y0 + (y1 - y0) * i / steps;
		frame(p, 1, &x, &y, 1);
	}
	sleep_ms(ms);
	frame(p, 0, NULL, NULL, 1);
}

static void pinch(struct panel *p, int cx, int cy, int d0, int d1, int steps, int ms)
{
	int x[2] = {cx - d0 / 2, cx + d0 / 2}, y[2] = {cy, cy};

	frame(p, 2, x, y, 0);
	for (int i = 1; i <= steps; i++) {
		int d = d0 + (d1 - d0) * i / steps;

		sleep_ms(ms);
		x[0] = cx - d / 2;
		x[1] = cx + d / 2;
		frame(p, 2, x, y, 2);
	}
	sleep_ms(ms);
	frame(p, 0, NULL, NULL, 2);
}

static void hold(struct panel *p, int x, int y, int ms)
{
	frame(p, 1, &x, &y, 0);
	sleep_ms(ms);
	frame(p, 0, NULL, NULL, 1);
}

static int setup(struct panel *p)
{
	static const int mt[] = {ABS_MT_SLOT, ABS_MT_TRACKING_ID, ABS_MT_POSITION_X,
				 ABS_MT_POSITION_Y};
	struct uinput_abs_setup abs = {.absinfo = {.maximum = AXIS_MAX}};
	struct uinput_setup dev = {
	    .id = {.bustype = BUS_VIRTUAL, .vendor = 0x1d6b, .product = 0x0105}};

	if (ioctl(p->fd, UI_SET_EVBIT, EV_KEY) || ioctl(p->fd, UI_SET_KEYBIT, BTN_TOUCH) ||
	    ioctl(p->fd, UI_SET_EVBIT, EV_ABS) || ioctl(p->fd, UI_SET_PROPBIT, INPUT_PROP_DIRECT))
		return -1;
	for (int code = ABS_X; code <= ABS_Y; code++) {
		abs.code = (unsigned short)code;
		if (ioctl(p->fd, UI_SET_ABSBIT, code) || ioctl(p->fd, UI_ABS_SETUP, &abs))
			return -1;
	}
	for (size_t i = 0; !p->single && i < sizeof(mt) / sizeof(mt[0]); i++) {
		abs.code = (unsigned short)mt[i];
		abs.absinfo.maximum = mt[i] == ABS_MT_SLOT	    ? 1
				      : mt[i] == ABS_MT_TRACKING_ID ? 65535
								    : AXIS_MAX;
		if (ioctl(p->fd, UI_SET_ABSBIT, mt[i]) || ioctl(p->fd, UI_ABS_SETUP, &abs))
			return -1;
	}
	snprintf(dev.name, sizeof(dev.name), "touch-inject touchscreen");
	return ioctl(p->fd, UI_DEV_SETUP, &dev) || ioctl(p->fd, UI_DEV_CREATE) ? -1 : 0;
}

/* One command line; false at quit. */
static bool run(struct panel *p, const char *line)
{
	char what[16];
	int v[6] = {0};
	int n =
	    sscanf(line, "%15s %d %d %d %d %d %d", what, &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]);

	if (n < 1)
		return true;
	if (!strcmp(what, "quit"))
		return false;
	if (!strcmp(what, "drag") && n == 7)
		drag(p, v[0], v[1], v[2], v[3], v[4] > 0 ? v[4] : 1, v[5]);
	else if (!strcmp(what, "pinch") && n == 7)
		pinch(p, v[0], v[1], v[2], v[3], v[4] > 0 ? v[4] : 1, v[5]);
	else if (!strcmp(what, "tap") && n == 3)
		hold(p, v[0], v[1], 40);
	else if (!strcmp(what, "doubletap") && n == 3) {
		hold(p, v[0], v[1], 40);
		sleep_ms(120);
		hold(p, v[0], v[1], 40);
	} else if (!strcmp(what, "hold") && n == 4)
		hold(p, v[0], v[1], v[2]);
	else {
		fprintf(stderr, "touch_inject: cannot read: %s", line);
		return true;
	}
	printf("done %s\n", what);
	fflush(stdout);
	return true;
}

int main(int argc, char **argv)
{
	struct panel p = {.single = argc == 3 && !strcmp(argv[1], "-s")};
	const char *fifo = argv[argc - 1];
	char line[256];
	FILE *in = NULL;
	int ret = 1;

	if (argc < 2 || argc > 3 || (argc == 3 && !p.single)) {
		fprintf(stderr, "usage: touch_inject [-s] FIFO\n");
		return 2;
	}
	p.fd = open("/dev/uinput", O_WRONLY | O_NONBLOCK | O_CLOEXEC);
	if (p.fd < 0 || setup(&p)) {
		fprintf(stderr, "touch_inject: uinput: %s (is uinput loaded?)\n", strerror(errno));
		goto out;
	}
	/* O_RDWR: the FIFO never reads EOF between writers. */
	if ((mkfifo(fifo, 0600) && errno != EEXIST) || !(in = fopen(fifo, "r+"))) {
		fprintf(stderr, "touch_inject: %s: %s\n", fifo, strerror(errno));
		goto out;
	}
	printf("ready\n");
	fflush(stdout);
	while (fgets(line, sizeof(line), in) && run(&p, line))
		;
	ret = 0;
out:
	if (in)
		fclose(in);
	if (p.fd >= 0) {
		ioctl(p.fd, UI_DEV_DESTROY);
		close(p.fd);
	}
	return ret;
}
