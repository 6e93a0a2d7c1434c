/* Remote control's words (src/state/remote.c): every command a payload
 * may give, and the attacks a broker's client could send (a path, a
 * wildcard, control bytes, a NUL inside, a long payload, numbers out of
 * range), each refused with what was expected; the state's JSON escaped. */
#include "state/remote.h"

#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>

static struct remote_cmd parse_ok(const char *text)
{
	struct remote_cmd c;
	char why[200] = "";

	assert_int_equal(remote_parse(text, strlen(text), &c, why, sizeof(why)), 0);
	assert_string_equal(why, "");
	return c;
}

/* Refused, and the reason has `expected` in it. */
static void refused(const void *payload, size_t len, const char *expected)
{
	struct remote_cmd c;
	char why[200] = "";

	assert_int_equal(remote_parse(payload, len, &c, why, sizeof(why)), -EINVAL);
	if (!strstr(why, expected))
		fail_msg("'%s' does not say '%s'", why, expected);
}

static void refused_text(const char *text, const char *expected)
{
	refused(text, strlen(text), expected);
}

static void test_every_command(void **state)
{
	struct remote_cmd c;
	char d[64];

	(void)state;
	c = parse_ok("model next");
	assert_int_equal(c.verb, REMOTE_MODEL);
	assert_int_equal(c.step, 1);
	c = parse_ok("model prev");
	assert_int_equal(c.step, -1);
	c = parse_ok("matcap next");
	assert_int_equal(c.verb, REMOTE_MATCAP);
	assert_int_equal(c.step, 1);
	c = parse_ok("matcap 12");
	assert_int_equal(c.index, 12);
	assert_int_equal(c.step, 0);
	c = parse_ok("stop 3");
	assert_int_equal(c.verb, REMOTE_STOP);
	assert_int_equal(c.index, 3);
	c = parse_ok("stop prev");
	assert_int_equal(c.step, -1);
	c = parse_ok("variant next");
	assert_int_equal(c.verb, REMOTE_VARIANT);
	c = parse_ok("language pt-BR");
	assert_int_equal(c.verb, REMOTE_LANGUAGE);
	assert_string_equal(c.language, "pt-BR");
	c = parse_ok("screen on");
	assert_int_equal(c.verb, REMOTE_SCREEN);
	assert_true(c.on);
	c = parse_ok("screen off");
	assert_false(c.on);
	c = parse_ok("reload\n"); /* mosquitto_pub -l's newline */
	assert_int_equal(c.verb, REMOTE_RELOAD);
	remote_describe(&c, d, sizeof(d));
	assert_string_equal(d, "reload");
	c = parse_ok("matcap 999");
	remote_describe(&c, d, sizeof(d));
	assert_string_equal(d, "matcap 999");
}

/* A command can never name a file: a path where a number or a word goes
 * is refused, whatever it looks like. */
static void test_paths_refused(void **state)
{
	(void)state;
	refused_text("matcap /etc/shadow", "matcap N");
	refused_text("matcap ../../x.png", "matcap N");
	refused_text("matcap gold.png", "matcap N");
	refused_text("model /tmp/evil.glb", "'model next' or 'model prev'");
	refused_text("language ../de", "BCP 47");
	refused_text("/etc/passwd", "no command");
}

static void test_malformed_refused(void **state)
{
	static const char nul[] = "model next\0rm";

	(void)state;
	refused("", 0, "empty");
	refused("\n", 1, "empty");
	refused(nul, sizeof(nul) - 1, "byte 11 is 0x00");
	refused_text("model\tnext", "byte 6 is 0x09");
	refused_text("matcap n\xc3\xa9xt", "printable ASCII");
	refused_text("model  next", "one word after the command");
	refused_text(" model next", "no command");
	refused_text("model next now", "one word");
	refused_text("Model next", "no command");
	refused_text("model", "'model next'");
	refused_text("matcap 0", "1-999");
	refused_text("matcap 1000", "1-999");
	refused_text("matcap 012", "1-999");
	refused_text("matcap -1", "1-999");
	refused_text("stop 65", "1-64");
	refused_text("variant prev", "'variant next'");
	refused_text("screen dim", "'screen on'");
	refused_text("reload now", "'reload' alone");
	refused_text("language deutsch", "BCP 47");
	refused_text("language de-xx", "BCP 47");
	refused_text("#", "no command");
	{
		char big[200];

		memset(big, 'a', sizeof(big));
		refused(big, sizeof(big), "longer than 64");
	}
}

static void test_broker_and_topic(void **state)
{
	char host[80], why[200];
	int port;

	(void)state;
	assert_int_equal(
	    remote_broker_parse("broker.lan", host, sizeof(host), &port, 1883, why, sizeof(why)),
	    0);
	assert_string_equal(host, "broker.lan");
	assert_int_equal(port, 1883);
	assert_int_equal(remote_broker_parse("127.0.0.1:18830", host, sizeof(host), &port, 1883,
					     why, sizeof(why)),
			 0);
	assert_string_equal(host, "127.0.0.1");
	assert_int_equal(port, 18830);
	assert_int_equal(
	    remote_broker_parse("host:0", host, sizeof(host), &port, 1883, why, sizeof(why)),
	    -EINVAL);
	assert_non_null(strstr(why, "1-65535"));
	assert_int_equal(
	    remote_broker_parse("host:70000", host, sizeof(host), &port, 1883, why, sizeof(why)),
	    -EINVAL);
	assert_int_equal(
	    remote_broker_parse("a b", host, sizeof(host), &port, 1883, why, sizeof(why)), -EINVAL);
	assert_non_null(strstr(why, "HOST:PORT"));
	assert_int_equal(remote_topic_check("kiosk/vitrine-3", why, sizeof(why)), 0);
	assert_int_equal(remote_topic_check("kiosk/#", why, sizeof(why)), -EINVAL);
	assert_int_equal(remote_topic_check("kiosk/+/x", why, sizeof(why)), -EINVAL);
	assert_int_equal(remote_topic_check("kiosk//x", why, sizeof(why)), -EINVAL);
	assert_int_equal(remote_topic_check("$SYS/x", why, sizeof(why)), -EINVAL);
	assert_int_equal(remote_topic_check("kiosk/", why, sizeof(why)), -EINVAL);
	assert_non_null(strstr(why, "no wildcard"));
}

static void test_state_json(void **state)
{
	struct remote_state st = {.model = "a\"b\\c.glb",
				  .matcap = NULL,
				  .stop = 2,
				  .screen_on = true,
				  .error = "x:1: bad\n"};
	char buf[256], tiny[20];
	int len;

	(void)state;
	len = remote_state_json(&st, buf, sizeof(buf));

	assert_int_equal(len, (int)strlen(buf));
	assert_string_equal(buf, "{\"model\":\"a\\\"b\\\\c.glb\",\"matcap\":\"\",\"stop\":2,"
				 "\"screen\":\"on\",\"error\":\"x:1: bad\\u000a\"}");
	assert_int_equal(remote_state_json(&st, tiny, sizeof(tiny)), -ENOSPC);
	assert_string_equal(remote_basename("/srv/models/knot.glb"), "knot.glb");
	assert_string_equal(remote_basename("knot.glb"), "knot.glb");
	assert_null(remote_basename(NULL));
}

/* A leader's step: read back as written; anything else refused whole. */
static void test_sync_words(void **state)
{
	struct remote_sync a = {1795886943123ull, 1, 4, -1}, b;
	static const char *const bad[] = {
	    "at=1795886943123 model=1 matcap=4",	       /* a key missing */
	    "at=1795886943123 matcap=4 model=1 stop=0",	       /* out of order */
	    "at=1795886943123 model=1 matcap=4 stop=0 x=1",    /* one more */
	    "at=1795886943123 model=1 matcap=999 stop=0",      /* past the range */
	    "at=1795886943123 model=-2 matcap=4 stop=0",       /* below it */
	    "at=1795886943123 model=01 matcap=4 stop=0",       /* a leading zero */
	    "at=1795886943123  model=1 matcap=4 stop=0",       /* two spaces */
	    "at=-1 model=1 matcap=4 stop=0",		       /* no time */
	    "at=1795886943123 model=1 matcap=/etc/x stop=0",   /* a path */
	    "at=99999999999999999999 model=1 matcap=4 stop=0", /* overflow */
	};
	char buf[REMOTE_SYNC_MAX + 1], why[200];
	int len;

	(void)state;
	len = remote_sync_format(&a, buf, sizeof(buf));

	assert_string_equal(buf, "at=1795886943123 model=1 matcap=4 stop=-1");
	assert_int_equal(len, (int)strlen(buf));
	assert_int_equal(remote_sync_parse(buf, strlen(buf), &b, why, sizeof(why)), 0);
	assert_true(b.at_ms == a.at_ms);
	assert_int_equal(b.model, 1);
	assert_int_equal(b.matcap, 4);
	assert_int_equal(b.stop, -1);
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		why[0] = '\0';
		assert_int_equal(remote_sync_parse(bad[i], strlen(bad[i]), &b, why, sizeof(why)),
				 -EINVAL);
		if (!strstr(why, "expected 'at=MS model=M matcap=C stop=S'"))
			fail_msg("'%s': '%s'", bad[i], why);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
	    cmocka_unit_test(test_every_command),     cmocka_unit_test(test_paths_refused),
	    cmocka_unit_test(test_malformed_refused), cmocka_unit_test(test_broker_and_topic),
	    cmocka_unit_test(test_state_json),	      cmocka_unit_test(test_sync_words),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}
