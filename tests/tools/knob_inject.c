/* A rotary knob for the virtual board (tests/e2e/knob-board.sh): a uinput
 * device, "knob-inject knob", as the kernel's rotary-encoder driver makes
 * one with rotary-encoder,relative-axis (REL_X, one count and a report a
 * detent), with KEY_ENTER beside it for the knob's press.
 *
 *   knob_inject FIFO
 *
 * reads lines from FIFO:
 *   turn N MS     N detents (negative: anticlockwise), MS apart
 *   press         the key down, 60 ms, up
 *   hold MS       the key down, MS, up
 *   quit
 * and after each prints "done WHAT" on stdout ("ready" once it exists). */
#include <errno.h>
#include <fcntl.h>
#include <linux/uinput.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static void sleep_ms(long ms)
{
	struct timespec ts = {ms / 1000, (ms % 1000) * 1000000L};

	while (nanosleep(&ts, &ts) && errno == EINTR)
		;
}

static void emit(int fd, int type, int code, int value)
{
	struct input_event ev = {
	    .type = (unsigned short)type, .code = (unsigned short)code, .value = value};

	if (write(fd, &ev, sizeof(ev)) != (ssize_t)sizeof(ev))
		fprintf(stderr, "knob_inject: write: %s\n", strerror(errno));
}

static void report(int fd, int type, int code, int value)
{
	emit(fd, type, code, value);
	emit(fd, EV_SYN, SYN_REPORT, 0);
}

static int make_knob(void)
{
	struct uinput_setup setup = {.id = {.bustype = BUS_HOST, .vendor = 0x1, .product = 0x2}};
	int fd = open("/dev/uinput", O_WRONLY | O_CLOEXEC);

	if (fd < 0) {
		fprintf(stderr, "knob_inject: /dev/uinput: %s\n", strerror(errno));
		return -1;
	}
	snprintf(setup.name, sizeof(setup.name), "knob-inject knob");
	if (ioctl(fd, UI_SET_EVBIT, EV_REL) || ioctl(fd, UI_SET_RELBIT, REL_X) ||
	    ioctl(fd, UI_SET_EVBIT, EV_KEY) || ioctl(fd, UI_SET_KEYBIT, KEY_ENTER) ||
	    ioctl(fd, UI_DEV_SETUP, &setup) || ioctl(fd, UI_DEV_CREATE)) {
		fprintf(stderr, "knob_inject: uinput setup: %s\n", strerror(errno));
		close(fd);
		return -1;
	}
	return fd;
}

/* One command; 1 for quit, 0 done, -1 not understood. */
static int command(int fd, const char *line)
{
	int n, ms;

	if (sscanf(line, "turn %d %d", &n, &ms) == 2) {
		for (int i = 0; i < abs(n); i++) {
			if (i)
				sleep_ms(ms);
			report(fd, EV_REL, REL_X, n > 0 ? 1 : -1);
		}
	} else if (!strncmp(line, "press", 5)) {
		report(fd, EV_KEY, KEY_ENTER, 1);
		sleep_ms(60);
		report(fd, EV_KEY, KEY_ENTER, 0);
	} else if (sscanf(line, "hold %d", &ms) == 1) {
		report(fd, EV_KEY, KEY_ENTER, 1);
		sleep_ms(ms);
		report(fd, EV_KEY, KEY_ENTER, 0);
	} else if (!strncmp(line, "quit", 4)) {
		return 1;
	} else {
		return -1;
	}
	return 0;
}

int main(int argc, char **argv)
{
	char line[128];
	FILE *in;
	int fd, rc = 0;

	if (argc != 2) {
		fprintf(stderr, "usage: knob_inject FIFO\n");
		return 2;
	}
	if (mkfifo(argv[1], 0600) && errno != EEXIST) {
		fprintf(stderr, "knob_inject: %s: %s\n", argv[1], strerror(errno));
		return 1;
	}
	fd = make_knob();
	if (fd < 0)
		return 1;
	printf("ready\n");
	fflush(stdout);
	/* Opened read-write: the FIFO stays open between writers. */
	in = fopen(argv[1], "r+");
	while (in && fgets(line, sizeof(line), in) && (rc = command(fd, line)) != 1) {
		printf(rc ? "unknown %s" : "done %s", line);
		fflush(stdout);
	}
	ioctl(fd, UI_DEV_DESTROY);
	close(fd);
	if (in)
		fclose(in);
	return 0;
}
