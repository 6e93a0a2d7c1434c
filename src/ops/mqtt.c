/* Remote control over MQTT: see mqtt.h. The connection is this file's
 * thread's (libmosquitto in its threaded mode, driven by mosquitto_loop
 * here, so the backoff and the stop are ours); the loop thread only takes
 * checked commands and queues a publish. */
#include "ops/mqtt.h"
#include "ops/mqtt_ha.h"
#include "util/log.h"

#include <errno.h>
#include <mosquitto.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <time.h>
#include <unistd.h>

#define BACKOFF_MAX_S 60
#define STATE_MAX     2048

struct mqtt_link {
	struct mosquitto *mosq;
	struct mqtt_topics t;
	char host[REMOTE_HOST_MAX + 1];
	int port;
	bool home_assistant;
	int efd;
	pthread_t thread;
	bool started;
	atomic_bool stop;
	atomic_bool connected;
	pthread_mutex_t lock; /* the queue, the state and the wait below */
	pthread_cond_t wake;
	struct remote_cmd queue[MQTT_QUEUE];
	int queued;
	char state[STATE_MAX]; /* the last state asked for; "": none yet */
	bool said_down;	       /* this outage was said (the thread's own) */
	enum mqtt_sync sync;
	char step_topic[REMOTE_TOPIC_MAX + 16]; /* GROUP/step */
	struct remote_sync step; /* a follower's newest, not taken; a leader's last */
	bool step_waiting;	 /* a follower's: not taken yet; a leader's: one sent */
};

/* The broker's CONNACK: subscribed and announced again on each
 * connection (a restarted broker without persistence forgets both). */
static void on_connect(struct mosquitto *mosq, void *ctx, int rc)
{
	struct mqtt_link *l = ctx;
	char state[STATE_MAX];
	struct remote_sync step;
	bool leader_step;

	if (rc) {
		/* Said once per outage, as a broker not there is: the
		 * retries go on, with the same answer each time. */
		if (!l->said_down)
			log_err("mqtt: %s:%d refused the connection: %s (a user name and password "
				"come from LoadCredential=mqtt:FILE); tried again after up to %d s",
				l->host, l->port, mosquitto_connack_string(rc), BACKOFF_MAX_S);
		l->said_down = true;
		return;
	}
	log_info("mqtt: connected to %s:%d; commands on %s", l->host, l->port, l->t.command);
	l->said_down = false;
	atomic_store(&l->connected, true);
	mosquitto_subscribe(mosq, NULL, l->t.command, 1);
	if (l->sync == MQTT_SYNC_FOLLOWER)
		mosquitto_subscribe(mosq, NULL, l->step_topic, 1);
	mosquitto_publish(mosq, NULL, l->t.availability, 6, "online", 1, true);
	pthread_mutex_lock(&l->lock);
	memcpy(state, l->state, sizeof(state));
	step = l->step;
	leader_step = l->sync == MQTT_SYNC_LEADER && l->step_waiting;
	pthread_mutex_unlock(&l->lock);
	if (state[0])
		mosquitto_publish(mosq, NULL, l->t.state, (int)strlen(state), state, 1, true);
	/* A restarted broker forgot the retained step: the followers that
	 * start meanwhile find it again. */
	if (leader_step)
		mqtt_link_publish_sync(l, &step);
	if (l->home_assistant)
		mqtt_ha_announce(mosq, &l->t);
}

static void wake_loop(struct mqtt_link *l)
{
	uint64_t one = 1;

	if (write(l->efd, &one, sizeof(one)) < 0)
		log_debug("mqtt: the loop's eventfd: %s", strerror(errno));
}

/* A leader's step: the newest replaces one not taken yet. */
static void take_step(struct mqtt_link *l, const struct mosquitto_message *m)
{
	struct remote_sync s;
	char why[200];

	if (m->payloadlen < 0 ||
	    remote_sync_parse(m->payload, (size_t)m->payloadlen, &s, why, sizeof(why))) {
		log_warn("mqtt: %s: a leader's step of %d bytes ignored: %s", m->topic,
			 m->payloadlen, why);
		return;
	}
	pthread_mutex_lock(&l->lock);
	l->step = s;
	l->step_waiting = true;
	pthread_mutex_unlock(&l->lock);
	wake_loop(l);
}

/* A payload checked here, on the connection's thread: the loop sees a
 * valid command or nothing. */
static void on_message(struct mosquitto *mosq, void *ctx, const struct mosquitto_message *m)
{
	struct mqtt_link *l = ctx;
	struct remote_cmd cmd;
	char why[160];
	bool full;

	(void)mosq;
	if (l->sync == MQTT_SYNC_FOLLOWER && !strcmp(m->topic, l->step_topic)) {
		take_step(l, m);
		return;
	}
	if (strcmp(m->topic, l->t.command))
		return;
	if (m->payloadlen < 0 ||
	    remote_parse(m->payload, (size_t)m->payloadlen, &cmd, why, sizeof(why))) {
		log_warn("mqtt: %s: a payload of %d bytes ignored: %s", m->topic, m->payloadlen,
			 why);
		return;
	}
	pthread_mutex_lock(&l->lock);
	full = l->queued == MQTT_QUEUE;
	if (!full)
		l->queue[l->queued++] = cmd;
	pthread_mutex_unlock(&l->lock);
	if (full)
		log_warn("mqtt: %s: %d commands wait already; this one is dropped", m->topic,
			 MQTT_QUEUE);
	else
		wake_loop(l);
}

static void on_disconnect(struct mosquitto *mosq, void *ctx, int rc)
{
	struct mqtt_link *l = ctx;

	(void)mosq;
	(void)rc;
	atomic_store(&l->connected, false);
}

/* Sleep s seconds, or until mqtt_link_free wakes us. */
static void wait_s(struct mqtt_link *l, int s)
{
	struct timespec until;

	clock_gettime(CLOCK_MONOTONIC, &until);
	until.tv_sec += s;
	pthread_mutex_lock(&l->lock);
	while (!atomic_load(&l->stop) &&
	       pthread_cond_timedwait(&l->wake, &l->lock, &until) != ETIMEDOUT)
		;
	pthread_mutex_unlock(&l->lock);
}

static void say_down(struct mqtt_link *l, int rc, int backoff)
{
	if (l->said_down)
		return;
	l->said_down = true;
	log_warn("mqtt: %s:%d: %s (%d); the kiosk runs on without remote control and tries again "
		 "(after %d s, then up to every %d s)",
		 l->host, l->port, rc == MOSQ_ERR_ERRNO ? strerror(errno) : mosquitto_strerror(rc),
		 rc, backoff, BACKOFF_MAX_S);
}

/* Connect, run, and after a failure or a loss wait 1, 2, 4 ... 60 s. */
static void *run(void *arg)
{
	struct mqtt_link *l = arg;
	int backoff = 1;

	mqtt_ha_credentials(l->mosq);
	while (!atomic_load(&l->stop)) {
		int rc = mosquitto_connect_async(l->mosq, l->host, l->port, 30);

		while (rc == MOSQ_ERR_SUCCESS && !atomic_load(&l->stop))
			rc = mosquitto_loop(l->mosq, 500, 1);
		if (atomic_load(&l->stop))
			break;
		if (atomic_load(&l->connected) || rc == MOSQ_ERR_CONN_LOST)
			backoff = 1;
		atomic_store(&l->connected, false);
		say_down(l, rc, backoff);
		wait_s(l, backoff);
		backoff = backoff * 2 > BACKOFF_MAX_S ? BACKOFF_MAX_S : backoff * 2;
	}
	if (atomic_load(&l->connected)) {
		mosquitto_publish(l->mosq, NULL, l->t.availability, 7, "offline", 1, true);
		mosquitto_loop(l->mosq, 100, 1);
		mosquitto_disconnect(l->mosq);
		mosquitto_loop(l->mosq, 100, 1);
	}
	return NULL;
}

/* The client, its last will, TLS. 0 or -EINVAL (logged). */
static int configure(struct mqtt_link *l, const struct mqtt_config *cfg)
{
	int rc;

	mosquitto_threaded_set(l->mosq, true);
	mosquitto_connect_callback_set(l->mosq, on_connect);
	mosquitto_message_callback_set(l->mosq, on_message);
	mosquitto_disconnect_callback_set(l->mosq, on_disconnect);
	mosquitto_reconnect_delay_set(l->mosq, 1, BACKOFF_MAX_S, true);
	rc = mosquitto_will_set(l->mosq, l->t.availability, 7, "offline", 1, true);
	if (!rc && cfg->tls) {
		const char *ca = cfg->ca_file && cfg->ca_file[0] ? cfg->ca_file : NULL;

		rc = mosquitto_tls_set(l->mosq, ca, ca ? NULL : "/etc/ssl/certs", NULL, NULL, NULL);
		if (rc)
			log_err("mqtt: [mqtt] ca_file = '%s': %s: expected a readable PEM file",
				ca ? ca : "", mosquitto_strerror(rc));
	}
	return rc ? -EINVAL : 0;
}

/* The broker and topic settings checked: 0, or -EINVAL (logged). */
static int settings(struct mqtt_link *l, const struct mqtt_config *cfg)
{
	char why[200];

	if (remote_broker_parse(cfg->broker, l->host, sizeof(l->host), &l->port,
				cfg->tls ? 8883 : 1883, why, sizeof(why))) {
		log_err("mqtt: [mqtt] broker = %s; remote control is off", why);
		return -EINVAL;
	}
	if (mqtt_ha_topics(&l->t, cfg->topic, why, sizeof(why))) {
		log_err("mqtt: [mqtt] topic = %s; remote control is off", why);
		return -EINVAL;
	}
	l->home_assistant = cfg->home_assistant;
	l->sync = cfg->sync;
	if (cfg->sync != MQTT_SYNC_OFF && cfg->group && cfg->group[0] &&
	    remote_topic_check(cfg->group, why, sizeof(why))) {
		log_err("mqtt: [mqtt] group = %s; remote control is off", why);
		return -EINVAL;
	}
	snprintf(l->step_topic, sizeof(l->step_topic), "%s/step",
		 cfg->group && cfg->group[0] ? cfg->group : "kiosk/group");
	return 0;
}

struct mqtt_link *mqtt_link_new(const struct mqtt_config *cfg)
{
	struct mqtt_link *l;

	if (!cfg->broker || !cfg->broker[0])
		return NULL;
	l = calloc(1, sizeof(*l));
	if (!l)
		return NULL;
	l->efd = eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
	pthread_mutex_init(&l->lock, NULL);
	pthread_cond_init(&l->wake, NULL);
	if (l->efd < 0 || settings(l, cfg))
		goto fail;
	mosquitto_lib_init();
	l->mosq = mosquitto_new(l->t.client_id, true, l);
	if (!l->mosq || configure(l, cfg))
		goto fail;
	if (pthread_create(&l->thread, NULL, run, l)) {
		log_err("mqtt: no thread for the connection; remote control is off");
		goto fail;
	}
	l->started = true;
	return l;
fail:
	mqtt_link_free(l);
	return NULL;
}

void mqtt_link_free(struct mqtt_link *l)
{
	if (!l)
		return;
	if (l->started) {
		pthread_mutex_lock(&l->lock);
		atomic_store(&l->stop, true);
		pthread_cond_signal(&l->wake);
		pthread_mutex_unlock(&l->lock);
		pthread_join(l->thread, NULL);
	}
	if (l->mosq) {
		mosquitto_destroy(l->mosq);
		mosquitto_lib_cleanup();
	}
	if (l->efd >= 0)
		close(l->efd);
	pthread_cond_destroy(&l->wake);
	pthread_mutex_destroy(&l->lock);
	free(l);
}

int mqtt_link_fd(const struct mqtt_link *l)
{
	return l ? l->efd : -1;
}

int mqtt_link_take(struct mqtt_link *l, struct remote_cmd *out, int max)
{
	uint64_t count;
	int n;

	if (!l)
		return 0;
	if (read(l->efd, &count, sizeof(count)) < 0 && errno != EAGAIN)
		log_debug("mqtt: the loop's eventfd: %s", strerror(errno));
	pthread_mutex_lock(&l->lock);
	n = l->queued < max ? l->queued : max;
	memcpy(out, l->queue, sizeof(*out) * (size_t)n);
	memmove(l->queue, l->queue + n, sizeof(*out) * (size_t)(l->queued - n));
	l->queued -= n;
	pthread_mutex_unlock(&l->lock);
	return n;
}

void mqtt_link_publish_state(struct mqtt_link *l, const struct remote_state *st)
{
	char json[STATE_MAX];
	int len;
	bool same;

	if (!l || (len = remote_state_json(st, json, sizeof(json))) < 0)
		return;
	pthread_mutex_lock(&l->lock);
	same = !strcmp(json, l->state);
	if (!same)
		memcpy(l->state, json, (size_t)len + 1);
	pthread_mutex_unlock(&l->lock);
	/* Queued for the connection's thread (threaded mode): no write here.
	 * Not connected: on_connect publishes the latest. */
	if (!same && atomic_load(&l->connected))
		mosquitto_publish(l->mosq, NULL, l->t.state, len, json, 1, true);
}

void mqtt_link_publish_sync(struct mqtt_link *l, const struct remote_sync *s)
{
	char payload[REMOTE_SYNC_MAX + 1];
	int len = remote_sync_format(s, payload, sizeof(payload));

	if (!l)
		return;
	pthread_mutex_lock(&l->lock);
	l->step = *s;
	l->step_waiting = true;
	pthread_mutex_unlock(&l->lock);
	/* Not connected: on_connect sends the last one. */
	if (atomic_load(&l->connected))
		mosquitto_publish(l->mosq, NULL, l->step_topic, len, payload, 1, true);
}

bool mqtt_link_take_sync(struct mqtt_link *l, struct remote_sync *out)
{
	bool waiting;

	if (!l)
		return false;
	pthread_mutex_lock(&l->lock);
	waiting = l->step_waiting;
	*out = l->step;
	l->step_waiting = false;
	pthread_mutex_unlock(&l->lock);
	return waiting;
}
