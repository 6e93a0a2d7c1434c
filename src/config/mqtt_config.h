/* [mqtt] in kiosk.ini: remote control over MQTT. Plain data, so that the
 * settings need not know the client (src/ops/mqtt.h). */
#ifndef MK_MQTT_CONFIG_H
#define MK_MQTT_CONFIG_H

#include <stdbool.h>

/* [mqtt] sync: kiosks that show one exhibit together. */
enum mqtt_sync { MQTT_SYNC_OFF, MQTT_SYNC_LEADER, MQTT_SYNC_FOLLOWER };

struct mqtt_config {
	char *broker;	     /* HOST[:PORT]; NULL or "": off (the default) */
	char *topic;	     /* kiosk/NAME; NULL: kiosk/ and the host's name */
	bool tls;	     /* TLS to the broker (port 8883 by default) */
	char *ca_file;	     /* the broker's CA (PEM); NULL: the system's */
	bool home_assistant; /* Home Assistant's MQTT discovery messages */
	enum mqtt_sync sync; /* a leader publishes its steps, followers take them */
	char *group;	     /* the topic they share; NULL: kiosk/group */
};

#endif
