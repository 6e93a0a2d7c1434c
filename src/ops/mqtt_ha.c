/* The broker's side of remote control: the topics, the credentials and
 * Home Assistant's discovery messages (see mqtt_ha.h). */
#include "ops/mqtt_ha.h"
#include "util/file.h"
#include "util/log.h"

#include <errno.h>
#include <mosquitto.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The credential file is a user name and a password: small. */
#define CREDENTIALS_MAX 1024

int mqtt_ha_topics(struct mqtt_topics *t, const char *topic, char *why, size_t n)
{
	char host[64] = "kiosk";

	if (!topic || !topic[0]) {
		if (gethostname(host, sizeof(host) - 1))
			strcpy(host, "kiosk");
		host[strcspn(host, ".")] = '\0';
		snprintf(t->base, sizeof(t->base), "kiosk/%s", host);
	} else {
		snprintf(t->base, sizeof(t->base), "%s", topic);
	}
	if (remote_topic_check(topic && topic[0] ? topic : t->base, why, n))
		return -EINVAL;
	snprintf(t->command, sizeof(t->command), "%s/command", t->base);
	snprintf(t->state, sizeof(t->state), "%s/state", t->base);
	snprintf(t->availability, sizeof(t->availability), "%s/availability", t->base);
	snprintf(t->node, sizeof(t->node), "%s", t->base);
	for (char *c = t->node; *c; c++)
		if (*c == '/' || *c == '.')
			*c = '_';
	snprintf(t->client_id, sizeof(t->client_id), "matcap-kiosk-%s", t->node);
	return 0;
}

void mqtt_ha_credentials(struct mosquitto *mosq)
{
	const char *dir = getenv("CREDENTIALS_DIRECTORY");
	unsigned char *data = NULL;
	char path[4096];
	char *user, *pass;
	size_t size;
	int ret;

	if (!dir)
		return;
	snprintf(path, sizeof(path), "%s/mqtt", dir);
	ret = file_read_all(path, CREDENTIALS_MAX, &data, &size);
	if (ret == -ENOENT)
		return;
	if (ret) {
		log_err("mqtt: %s: %s: expected a user name and a password, one a line (%d bytes "
			"at most); connecting without",
			path, strerror(-ret), CREDENTIALS_MAX);
		return;
	}
	/* file_read_all ends the data with a NUL past size. */
	user = (char *)data;
	pass = strchr(user, '\n');
	if (pass)
		*pass++ = '\0';
	if (pass)
		pass[strcspn(pass, "\r\n")] = '\0';
	user[strcspn(user, "\r")] = '\0';
	if (!user[0])
		log_err("mqtt: %s:1: an empty user name: expected a user name, then the password "
			"on line 2; connecting without",
			path);
	else
		mosquitto_username_pw_set(mosq, user, pass && pass[0] ? pass : NULL);
	explicit_bzero(data, size);
	free(data);
}

/* The device every entity belongs to, as discovery's JSON has it. */
static void device(char *buf, size_t n, const struct mqtt_topics *t)
{
	snprintf(buf, n,
		 "\"availability_topic\":\"%s\",\"device\":{\"identifiers\":[\"%s\"],"
		 "\"name\":\"%s\",\"manufacturer\":\"matcap-kiosk\"}",
		 t->availability, t->node, t->base);
}

static void announce(struct mosquitto *mosq, const struct mqtt_topics *t, const char *component,
		     const char *id, const char *fields)
{
	char topic[256], payload[1024], dev[512];
	int len;

	device(dev, sizeof(dev), t);
	snprintf(topic, sizeof(topic), "homeassistant/%s/%s/%s/config", component, t->node, id);
	len = snprintf(payload, sizeof(payload), "{\"unique_id\":\"%s_%s\",%s,%s}", t->node, id,
		       fields, dev);
	if (len > 0 && (size_t)len < sizeof(payload))
		mosquitto_publish(mosq, NULL, topic, len, payload, 1, true);
}

static const struct {
	const char *id, *name, *payload;
} buttons[] = {
    {"next_model", "Next model", "model next"},
    {"prev_model", "Previous model", "model prev"},
    {"next_matcap", "Next matcap", "matcap next"},
    {"prev_matcap", "Previous matcap", "matcap prev"},
    {"next_stop", "Next stop", "stop next"},
    {"prev_stop", "Previous stop", "stop prev"},
    {"next_variant", "Next variant", "variant next"},
    {"reload", "Reload", "reload"},
};

static const struct {
	const char *id, *name, *field;
} sensors[] = {
    {"model", "Model", "model"},
    {"matcap", "Matcap", "matcap"},
    {"stop", "Stop", "stop"},
    {"error", "Last error", "error"},
};

void mqtt_ha_announce(struct mosquitto *mosq, const struct mqtt_topics *t)
{
	char f[512];

	for (size_t i = 0; i < sizeof(buttons) / sizeof(buttons[0]); i++) {
		snprintf(f, sizeof(f),
			 "\"name\":\"%s\",\"command_topic\":\"%s\",\"payload_press\":\"%s\"",
			 buttons[i].name, t->command, buttons[i].payload);
		announce(mosq, t, "button", buttons[i].id, f);
	}
	for (size_t i = 0; i < sizeof(sensors) / sizeof(sensors[0]); i++) {
		snprintf(f, sizeof(f),
			 "\"name\":\"%s\",\"state_topic\":\"%s\",\"value_template\":\"{{ "
			 "value_json.%s }}\"",
			 sensors[i].name, t->state, sensors[i].field);
		announce(mosq, t, "sensor", sensors[i].id, f);
	}
	snprintf(f, sizeof(f),
		 "\"name\":\"Screen\",\"command_topic\":\"%s\",\"payload_on\":\"screen on\","
		 "\"payload_off\":\"screen off\",\"state_topic\":\"%s\",\"value_template\":\"{{ "
		 "value_json.screen }}\",\"state_on\":\"on\",\"state_off\":\"off\"",
		 t->command, t->state);
	announce(mosq, t, "switch", "screen", f);
}
