/* What src/ops/mqtt.c says to the broker besides commands and state: the
 * topics from [mqtt] topic, the credentials systemd hands the service
 * (LoadCredential=mqtt:...), and Home Assistant's discovery messages. */
#ifndef MK_MQTT_HA_H
#define MK_MQTT_HA_H

#include "state/remote.h"

#include <stddef.h>

struct mosquitto;

struct mqtt_topics {
	char base[REMOTE_TOPIC_MAX + 1];	  /* kiosk/NAME */
	char command[REMOTE_TOPIC_MAX + 16];	  /* BASE/command */
	char state[REMOTE_TOPIC_MAX + 16];	  /* BASE/state */
	char availability[REMOTE_TOPIC_MAX + 16]; /* BASE/availability */
	char node[REMOTE_TOPIC_MAX + 1];	  /* BASE with '_' for '/': ids */
	char client_id[REMOTE_TOPIC_MAX + 16];
};

/* From [mqtt] topic (NULL or "": kiosk/ and the host's name). 0, or
 * -EINVAL with why. */
int mqtt_ha_topics(struct mqtt_topics *t, const char *topic, char *why, size_t n);
/* $CREDENTIALS_DIRECTORY/mqtt: a user name on the first line, its
 * password on the second; none without it (said when it is unreadable). */
void mqtt_ha_credentials(struct mosquitto *mosq);
/* Home Assistant's MQTT discovery: a device with buttons, a switch for
 * the screen and sensors for what is shown (retained). */
void mqtt_ha_announce(struct mosquitto *mosq, const struct mqtt_topics *t);

#endif
