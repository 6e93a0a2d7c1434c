/* The kiosk and its camera helper talk over a SOCK_SEQPACKET socket with
 * dmabufs attached: a message and its descriptors arrive together, a
 * packet that is not one of ours is refused (its descriptors closed), and
 * the other side closing is told apart from "nothing yet". */
#include "camera/camera_proto.h"

#include <errno.h>
#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>
#include <cmocka.h>

static int pair(int sv[2])
{
	return socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, sv);
}

static void message_and_descriptors_arrive_together(void **state)
{
	struct camera_msg m = {.type = CAMERA_MSG_BUFFER}, got;
	int sv[2], fds[2], in[CAMERA_MAX_PLANES], n;
	char buf[8] = "";

	(void)state;
	assert_int_equal(pair(sv), 0);
	for (int i = 0; i < 2; i++) {
		fds[i] = memfd_create("plane", MFD_CLOEXEC);
		assert_true(fds[i] >= 0);
		assert_int_equal(write(fds[i], i ? "chroma" : "luma", i ? 6 : 4), i ? 6 : 4);
	}
	m.u.buffer.buffer = 3;
	m.u.buffer.fd_index[1] = 1;
	m.u.buffer.offset[1] = 4096;
	assert_int_equal(camera_msg_send(sv[0], &m, fds, 2), 0);
	assert_int_equal(camera_msg_recv(sv[1], &got, in, &n), 0);
	assert_int_equal(got.type, CAMERA_MSG_BUFFER);
	assert_int_equal(got.u.buffer.buffer, 3);
	assert_int_equal(got.u.buffer.offset[1], 4096);
	assert_int_equal(n, 2);
	/* The same files, through new descriptors, closed on exec. */
	assert_int_equal(pread(in[1], buf, 6, 0), 6);
	assert_memory_equal(buf, "chroma", 6);
	assert_true(fcntl(in[0], F_GETFD) & FD_CLOEXEC);
	for (int i = 0; i < 2; i++) {
		close(fds[i]);
		close(in[i]);
	}
	/* Nothing more: not the end. */
	assert_int_equal(camera_msg_recv(sv[1], &got, in, &n), -EAGAIN);
	close(sv[0]);
	assert_int_equal(camera_msg_recv(sv[1], &got, in, &n), -EPIPE);
	close(sv[1]);
}

static void a_foreign_packet_is_refused(void **state)
{
	struct camera_msg got;
	int sv[2], in[CAMERA_MAX_PLANES], n;

	(void)state;
	assert_int_equal(pair(sv), 0);
	assert_int_equal(send(sv[0], "hello", 5, 0), 5);
	assert_int_equal(camera_msg_recv(sv[1], &got, in, &n), -EPROTO);
	assert_int_equal(n, 0);
	close(sv[0]);
	close(sv[1]);
}

static void too_many_descriptors_are_refused(void **state)
{
	struct camera_msg m = {.type = CAMERA_MSG_FRAME};
	int sv[2], fds[CAMERA_MAX_PLANES + 1] = {0};

	(void)state;
	assert_int_equal(pair(sv), 0);
	assert_int_equal(camera_msg_send(sv[0], &m, fds, CAMERA_MAX_PLANES + 1), -EINVAL);
	close(sv[0]);
	/* The other side gone: an error, never SIGPIPE. */
	assert_int_equal(camera_msg_send(sv[1], &m, NULL, 0), -EPIPE);
	close(sv[1]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(message_and_descriptors_arrive_together),
	    cmocka_unit_test(a_foreign_packet_is_refused),
	    cmocka_unit_test(too_many_descriptors_are_refused),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
