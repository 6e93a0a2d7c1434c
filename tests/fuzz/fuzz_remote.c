/* libFuzzer: remote control's payload parser (src/state/remote.c) on any
 * bytes, as a broker hands a payload over (a length, no NUL). Checked
 * beyond the sanitizers: an accepted command is one of the words with a
 * number in range and no '/' anywhere (a command never names a file), and
 * the journal's words for it parse back to the same command, as a
 * leader's step read back does; the same
 * bytes as a topic, a broker or a state's strings never overflow. */
#include "state/remote.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void accepted(const struct remote_cmd *c)
{
	struct remote_cmd again;
	char said[64], why[160];

	if (c->index < 0 || c->index > REMOTE_MATCAP_MAX || (c->step && c->index) ||
	    strchr(c->language, '/') || strchr(c->language, '.'))
		abort();
	if (c->verb == REMOTE_STOP && c->index > REMOTE_STOP_MAX)
		abort();
	remote_describe(c, said, sizeof(said));
	if (remote_parse(said, strlen(said), &again, why, sizeof(why)) ||
	    memcmp(&again, c, sizeof(again)))
		abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct remote_cmd c;
	struct remote_sync step;
	struct remote_state st = {0};
	char why[160], host[REMOTE_HOST_MAX + 1], json[512];
	char *text;
	int port;

	if (!remote_parse(data, size, &c, why, sizeof(why)))
		accepted(&c);
	if (!remote_sync_parse(data, size, &step, why, sizeof(why))) {
		char again[REMOTE_SYNC_MAX + 1];
		struct remote_sync back;
		int len = remote_sync_format(&step, again, sizeof(again));

		if (len >= (int)sizeof(again) || step.matcap < 0 || step.stop < -1 ||
		    remote_sync_parse(again, (size_t)len, &back, why, sizeof(why)) ||
		    back.at_ms != step.at_ms || back.model != step.model ||
		    back.matcap != step.matcap || back.stop != step.stop)
			abort();
	}
	if (!(text = malloc(size + 1)))
		return 0;
	memcpy(text, data, size);
	text[size] = '\0';
	remote_topic_check(text, why, sizeof(why));
	remote_broker_parse(text, host, sizeof(host), &port, 1883, why, sizeof(why));
	st.model = st.matcap = st.error = text;
	if (remote_state_json(&st, json, sizeof(json)) > (int)sizeof(json))
		abort();
	free(text);
	return 0;
}
