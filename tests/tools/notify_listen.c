/* Stands in for systemd's notify socket, so the tests see what the kiosk
 * tells the service manager without a running systemd:
 *   notify_listen SOCKET SECONDS
 * prints each datagram as one line, "MS TEXT" (milliseconds since start,
 * newlines shown as spaces), and exits after STOPPING=1 or SECONDS. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <poll.h>
#include <time.h>
#include <unistd.h>

static double now_ms(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
	struct sockaddr_un addr = {.sun_family = AF_UNIX};
	char msg[4096];
	double start = now_ms(), limit;
	int fd, stop = 0;

	if (argc != 3 || strlen(argv[1]) >= sizeof(addr.sun_path)) {
		fprintf(stderr, "usage: notify_listen SOCKET SECONDS\n");
		return 2;
	}
	limit = atof(argv[2]) * 1e3;
	strcpy(addr.sun_path, argv[1]);
	unlink(argv[1]);
	fd = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
	if (fd < 0 || bind(fd, (struct sockaddr *)&addr, sizeof(addr))) {
		perror(argv[1]);
		return 1;
	}
	while (!stop && now_ms() - start < limit) {
		struct pollfd p = {.fd = fd, .events = POLLIN};
		ssize_t n;

		if (poll(&p, 1, 50) <= 0)
			continue;
		n = recv(fd, msg, sizeof(msg) - 1, 0);
		if (n <= 0)
			continue;
		msg[n] = '\0';
		stop = strstr(msg, "STOPPING=1") != NULL;
		for (char *c = msg; *c; c++)
			if (*c == '\n')
				*c = ' ';
		printf("%.0f %s\n", now_ms() - start, msg);
		fflush(stdout);
	}
	close(fd);
	unlink(argv[1]);
	return 0;
}
