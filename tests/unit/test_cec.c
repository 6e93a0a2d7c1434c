/* HDMI-CEC against a fake adapter: the logical address claimed, the
 * messages that wake and standby a TV, byte for byte, and a TV that does
 * not answer said once, never retried in a loop. */
#include "display/cec.h"

#include <errno.h>
#include <linux/cec.h>
#include <sys/ioctl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include <cmocka.h>

struct fake {
	bool has_addr; /* the adapter is configured already */
	bool tv_answers;
	int claims; /* CEC_ADAP_S_LOG_ADDRS calls */
	struct cec_msg sent[16];
	int n_sent;
};

static int fake_ioctl(void *ctx, unsigned long request, void *arg)
{
	struct fake *f = ctx;

	if (request == CEC_ADAP_G_LOG_ADDRS) {
		struct cec_log_addrs *la = arg;

		memset(la, 0, sizeof(*la));
		la->num_log_addrs = f->has_addr;
		la->log_addr[0] = f->has_addr ? 8 : CEC_LOG_ADDR_INVALID;
		return 0;
	}
	if (request == CEC_ADAP_S_LOG_ADDRS) {
		struct cec_log_addrs *la = arg;

		f->claims++;
		assert_int_equal(la->log_addr_type[0], CEC_LOG_ADDR_TYPE_PLAYBACK);
		la->log_addr[0] = 4; /* Playback Device 1 */
		return 0;
	}
	if (request == CEC_ADAP_G_PHYS_ADDR) {
		*(uint16_t *)arg = 0x1000; /* 1.0.0.0: the TV's first HDMI input */
		return 0;
	}
	if (request == CEC_TRANSMIT) {
		struct cec_msg *m = arg;

		f->sent[f->n_sent++] = *m;
		/* Broadcasts are never acknowledged by a single device. */
		m->tx_status =
		    f->tv_answers || (m->msg[0] & 15) == 15 ? CEC_TX_STATUS_OK : CEC_TX_STATUS_NACK;
		return 0;
	}
	errno = ENOTTY;
	return -1;
}

static int warnings(FILE *log)
{
	char line[512];
	int n = 0;

	fflush(stderr);
	rewind(log);
	while (fgets(line, sizeof(line), log))
		n += strstr(line, "did not take") != NULL;
	return n;
}

static void test_wake_and_standby_bytes(void **state)
{
	struct fake f = {.tv_answers = true};
	struct cec_io io = {.ioctl = fake_ioctl, .ctx = &f};
	struct cec *c = cec_new_io(&io, "fake0");

	(void)state;
	assert_non_null(c);
	assert_int_equal(f.claims, 1);
	assert_int_equal(cec_power(c, false), 0);
	assert_int_equal(f.n_sent, 1);
	/* From 4 to the TV (0): <Standby>. */
	assert_int_equal(f.sent[0].len, 2);
	assert_int_equal(f.sent[0].msg[0], 0x40);
	assert_int_equal(f.sent[0].msg[1], 0x36);
	assert_int_equal(cec_power(c, true), 0);
	assert_int_equal(f.n_sent, 3);
	/* <Image View On>, then <Active Source> 1.0.0.0 to everyone. */
	assert_int_equal(f.sent[1].msg[0], 0x40);
	assert_int_equal(f.sent[1].msg[1], 0x04);
	assert_int_equal(f.sent[2].len, 4);
	assert_int_equal(f.sent[2].msg[0], 0x4f);
	assert_int_equal(f.sent[2].msg[1], 0x82);
	assert_int_equal(f.sent[2].msg[2], 0x10);
	assert_int_equal(f.sent[2].msg[3], 0x00);
	cec_free(c);
	/* An adapter that has an address keeps it: nothing is claimed. */
	f = (struct fake){.has_addr = true, .tv_answers = true};
	c = cec_new_io(&io, "fake0");
	assert_int_equal(f.claims, 0);
	assert_int_equal(cec_power(c, false), 0);
	assert_int_equal(f.sent[0].msg[0], 0x80);
	cec_free(c);
}

static void test_silent_tv_said_once(void **state)
{
	struct fake f = {.tv_answers = false};
	struct cec_io io = {.ioctl = fake_ioctl, .ctx = &f};
	FILE *log = tmpfile();
	int saved = dup(2);
	struct cec *c;

	(void)state;
	assert_non_null(log);
	dup2(fileno(log), 2);
	c = cec_new_io(&io, "fake0");
	assert_int_equal(cec_power(c, false), -EHOSTUNREACH);
	assert_int_equal(cec_power(c, true), -EHOSTUNREACH);
	assert_int_equal(cec_power(c, false), -EHOSTUNREACH);
	/* One message per change, no retry loop; one line in the journal. */
	assert_int_equal(f.n_sent, 3);
	assert_int_equal(warnings(log), 1);
	/* Back: said again only after it answered in between. */
	f.tv_answers = true;
	assert_int_equal(cec_power(c, true), 0);
	f.tv_answers = false;
	assert_int_equal(cec_power(c, false), -EHOSTUNREACH);
	assert_int_equal(warnings(log), 2);
	cec_free(c);
	dup2(saved, 2);
	close(saved);
	fclose(log);
}

static void test_missing_device(void **state)
{
	(void)state;
	assert_null(cec_new("/nonexistent/cec9"));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_wake_and_standby_bytes),
	    cmocka_unit_test(test_silent_tv_said_once),
	    cmocka_unit_test(test_missing_device),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
