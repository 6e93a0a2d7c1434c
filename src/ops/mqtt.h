/* Remote control over MQTT ([mqtt], libmosquitto): a thread of its own
 * connects, subscribes to TOPIC/command and keeps TOPIC/availability
 * ("online", or the broker's last will "offline") and TOPIC/state
 * (retained); a lost or absent broker is retried with backoff, said once
 * per outage. Each payload is checked on that thread (state/remote.h); a
 * valid command waits in a small locked queue and an eventfd wakes the
 * loop, which takes it. Nothing here blocks the loop: a publish is
 * queued for the thread. */
#ifndef MK_MQTT_H
#define MK_MQTT_H

#include "config/mqtt_config.h"
#include "state/remote.h"

struct mqtt_link;

/* Commands waiting at most; one more is dropped and said. */
#define MQTT_QUEUE 16

/* NULL when [mqtt] broker is not set, or the settings are wrong (logged:
 * the kiosk runs without remote control). */
struct mqtt_link *mqtt_link_new(const struct mqtt_config *cfg);
/* Stops the thread (the broker is told goodbye: availability "offline"). */
void mqtt_link_free(struct mqtt_link *l);
/* For poll(): readable while commands wait; -1 for NULL. */
int mqtt_link_fd(const struct mqtt_link *l);
/* Up to max waiting commands, oldest first; their count. */
int mqtt_link_take(struct mqtt_link *l, struct remote_cmd *out, int max);
/* The state shown: published (retained) when it differs from the last. */
void mqtt_link_publish_state(struct mqtt_link *l, const struct remote_state *st);
/* [mqtt] sync = leader: a step for the followers, on GROUP/step (retained:
 * a follower that starts later takes the latest). */
void mqtt_link_publish_sync(struct mqtt_link *l, const struct remote_sync *s);
/* [mqtt] sync = follower: the leader's newest step not taken yet; false
 * when there is none. */
bool mqtt_link_take_sync(struct mqtt_link *l, struct remote_sync *out);

#endif
