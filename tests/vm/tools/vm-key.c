/* vm-key: a virtual keyboard (uinput) for tests on the virtual board.
 *
 *   vm-key [-w MS] KEY...      create the keyboard, wait MS (500) for readers
 *                              to open it, press and release each KEY, exit
 *   vm-key -f FIFO             create the keyboard, then read lines from FIFO:
 *                              "KEY..." presses keys, "sleep MS", "quit"
 *
 * KEY is a name from linux/input-event-codes.h without KEY_ (ESC, ENTER,
 * SPACE, LEFT, RIGHT, UP, DOWN, TAB, Q, A, 1, F1, ...), or a number.  The
 * device is called "vm-key keyboard"; it appears as /dev/input/eventN.
 * Built by tests/vm/build.sh into the board's initramfs.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <linux/uinput.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static const struct {
	const char *name;
	int code;
} keys[] = {
	{ "ESC", KEY_ESC }, { "1", KEY_1 }, { "2", KEY_2 }, { "3", KEY_3 }, { "4", KEY_4 }, { "5", KEY_5 },
	{ "6", KEY_6 }, { "7", KEY_7 }, { "8", KEY_8 }, { "9", KEY_9 }, { "0", KEY_0 }, { "MINUS", KEY_MINUS },
	{ "EQUAL", KEY_EQUAL }, { "BACKSPACE", KEY_BACKSPACE }, { "TAB", KEY_TAB }, { "Q", KEY_Q }, { "W", KEY_W },
	{ "E", KEY_E }, { "R", KEY_R }, { "T", KEY_T }, { "Y", KEY_Y }, { "U", KEY_U }, { "I", KEY_I },
	{ "O", KEY_O }, { "P", KEY_P }, { "ENTER", KEY_ENTER }, { "LEFTCTRL", KEY_LEFTCTRL }, { "A", KEY_A },
	{ "S", KEY_S }, { "D", KEY_D }, { "F", KEY_F }, { "G", KEY_G }, { "H", KEY_H }, { "J", KEY_J },
	{ "K", KEY_K }, { "L", KEY_L }, { "LEFTSHIFT", KEY_LEFTSHIFT }, { "Z", KEY_Z }, { "X", KEY_X },
	{ "C", KEY_C }, { "V", KEY_V }, { "B", KEY_B }, { "N", KEY_N }, { "M", KEY_M }, { "COMMA", KEY_COMMA },
	{ "DOT", KEY_DOT }, { "SLASH", KEY_SLASH }, { "SPACE", KEY_SPACE }, { "F1", KEY_F1 }, { "F2", KEY_F2 },
	{ "F3", KEY_F3 }, { "F4", KEY_F4 }, { "F5", KEY_F5 }, { "F6", KEY_F6 }, { "F7", KEY_F7 }, { "F8", KEY_F8 },
	{ "F9", KEY_F9 }, { "F10", KEY_F10 }, { "F11", KEY_F11 }, { "F12", KEY_F12 }, { "HOME", KEY_HOME },
	{ "UP", KEY_UP }, { "PAGEUP", KEY_PAGEUP }, { "LEFT", KEY_LEFT }, { "RIGHT", KEY_RIGHT }, { "END", KEY_END },
	{ "DOWN", KEY_DOWN }, { "PAGEDOWN", KEY_PAGEDOWN }, { "INSERT", KEY_INSERT }, { "DELETE", KEY_DELETE },
	{ "PLUS", KEY_KPPLUS }, { "KPMINUS", KEY_KPMINUS }, { "R_BRACE", KEY_RIGHTBRACE },
	{ "L_BRACE", KEY_LEFTBRACE },
};

static int key_code(const char *name)
{
	char *end;
	long v;

	if (strncasecmp(name, "KEY_", 4) == 0)
		name += 4;
	for (size_t i = 0; i < sizeof(keys) / sizeof(keys[0]); i++)
		if (strcasecmp(name, keys[i].name) == 0)
			return keys[i].code;
	v = strtol(name, &end, 0);
	return *end == '\0' && v > 0 && v < KEY_MAX ? (int)v : -1;
}

static void sleep_ms(long ms)
{
	struct timespec ts = { ms / 1000, (ms % 1000) * 1000000L };
	while (nanosleep(&ts, &ts) != 0 && errno == EINTR)
		;
}

static int emit(int fd, int type, int code, int value)
{
	struct input_event ev;

	memset(&ev, 0, sizeof(ev));
	ev.type = (unsigned short)type;
	ev.code = (unsigned short)code;
	ev.value = value;
	return write(fd, &ev, sizeof(ev)) == (ssize_t)sizeof(ev) ? 0 : -1;
}

static int press(int fd, const char *name)
{
	int code = key_code(name);

	if (code < 0) {
		fprintf(stderr, "vm-key: unknown key '%s'\n", name);
		return -1;
	}
	if (emit(fd, EV_KEY, code, 1) || emit(fd, EV_SYN, SYN_REPORT, 0) || (sleep_ms(30), 0) ||
	    emit(fd, EV_KEY, code, 0) || emit(fd, EV_SYN, SYN_REPORT, 0)) {
		fprintf(stderr, "vm-key: write to uinput: %s\n", strerror(errno));
		return -1;
	}
	sleep_ms(30);
	return 0;
}

static int create_keyboard(void)
{
	struct uinput_setup setup;
	int fd = open("/dev/uinput", O_WRONLY | O_NONBLOCK | O_CLOEXEC);

	if (fd < 0) {
		fprintf(stderr, "vm-key: /dev/uinput: %s (is uinput loaded?)\n", strerror(errno));
		return -1;
	}
	if (ioctl(fd, UI_SET_EVBIT, EV_KEY) < 0)
		goto fail;
	for (int code = 1; code < 256; code++)
		if (ioctl(fd, UI_SET_KEYBIT, code) < 0)
			goto fail;
	memset(&setup, 0, sizeof(setup));
	setup.id.bustype = BUS_VIRTUAL;
	setup.id.vendor = 0x1d6b;
	setup.id.product = 0x0104;
	snprintf(setup.name, sizeof(setup.name), "vm-key keyboard");
	if (ioctl(fd, UI_DEV_SETUP, &setup) < 0 || ioctl(fd, UI_DEV_CREATE) < 0)
		goto fail;
	return fd;
fail:
	fprintf(stderr, "vm-key: uinput setup: %s\n", strerror(errno));
	close(fd);
	return -1;
}

int main(int argc, char **argv)
{
	const char *fifo = NULL;
	long wait_ms = 500;
	int opt, ret = 0;

	while ((opt = getopt(argc, argv, "f:w:h")) != -1) {
		switch (opt) {
		case 'f': fifo = optarg; break;
		case 'w': wait_ms = strtol(optarg, NULL, 0); break;
		default:
			fprintf(stderr, "usage: vm-key [-w MS] KEY...\n       vm-key -f FIFO\n");
			return opt == 'h' ? 0 : 2;
		}
	}
	if (!fifo && optind >= argc) {
		fprintf(stderr, "vm-key: no keys given\n");
		return 2;
	}
	int fd = create_keyboard();
	if (fd < 0)
		return 1;
	if (!fifo) {
		sleep_ms(wait_ms);
		for (int i = optind; i < argc && ret == 0; i++)
			ret = press(fd, argv[i]) ? 1 : 0;
		sleep_ms(100); /* let readers drain before the device goes */
	} else {
		if (mkfifo(fifo, 0600) != 0 && errno != EEXIST) {
			fprintf(stderr, "vm-key: mkfifo %s: %s\n", fifo, strerror(errno));
			ret = 1;
			goto out;
		}
		/* O_RDWR: the FIFO never reads EOF between writers. */
		FILE *in = fopen(fifo, "r+");
		char line[512];
		if (!in) {
			fprintf(stderr, "vm-key: %s: %s\n", fifo, strerror(errno));
			ret = 1;
			goto out;
		}
		while (fgets(line, sizeof(line), in)) {
			char *save = NULL, *tok = strtok_r(line, " \t\r\n", &save);
			if (!tok)
				continue;
			if (strcmp(tok, "quit") == 0)
				break;
			if (strcmp(tok, "sleep") == 0) {
				tok = strtok_r(NULL, " \t\r\n", &save);
				sleep_ms(tok ? strtol(tok, NULL, 0) : 0);
				continue;
			}
			for (; tok; tok = strtok_r(NULL, " \t\r\n", &save))
				press(fd, tok);
		}
		fclose(in);
	}
out:
	ioctl(fd, UI_DEV_DESTROY);
	close(fd);
	return ret;
}
