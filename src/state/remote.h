/* Remote control's words (MQTT, src/ops/mqtt.c): a command payload
 * checked as strictly as a settings line, the state published, the
 * broker and topic settings. Pure: bytes in, a checked command or a
 * reason out; no file, no socket. A command never names a path: matcaps
 * and stops go by number, models by step. */
#ifndef MK_REMOTE_H
#define MK_REMOTE_H

#include <stdbool.h>
#include <stddef.h>

/* The longest payload read; a longer one is refused whole. */
#define REMOTE_PAYLOAD_MAX 64
#define REMOTE_TOPIC_MAX   96
#define REMOTE_HOST_MAX	   64
#define REMOTE_MATCAP_MAX  999
#define REMOTE_STOP_MAX	   64

enum remote_verb {
	REMOTE_MODEL,	 /* step: next (+1) or prev (-1) */
	REMOTE_MATCAP,	 /* step, or index (1: the folder's first by name) */
	REMOTE_STOP,	 /* step, or index (1: [frame] stops' first) */
	REMOTE_VARIANT,	 /* step +1 only: next-variant */
	REMOTE_LANGUAGE, /* language: a BCP 47 tag such as de or pt-BR */
	REMOTE_SCREEN,	 /* on */
	REMOTE_RELOAD,	 /* as SIGHUP */
};

struct remote_cmd {
	enum remote_verb verb;
	int step;	   /* +1, -1; 0: by index */
	int index;	   /* 1-based; 0: by step */
	bool on;	   /* screen on / off */
	char language[12]; /* REMOTE_LANGUAGE only */
};

/* payload (len bytes, not NUL-terminated, as MQTT hands it) into *cmd:
 * 0, or -EINVAL with what was expected written into why (n bytes). */
int remote_parse(const void *payload, size_t len, struct remote_cmd *cmd, char *why, size_t n);
/* A command as a payload would say it ("matcap 3"): the journal's words. */
void remote_describe(const struct remote_cmd *cmd, char *buf, size_t n);

/* [mqtt] broker = HOST[:PORT]: host and port (default_port without one).
 * 0, or -EINVAL with why. */
int remote_broker_parse(const char *text, char *host, size_t host_n, int *port, int default_port,
			char *why, size_t n);
/* [mqtt] topic: levels of letters, digits, '-', '_' and '.' joined by '/',
 * no wildcard, no empty level, no leading '$'. 0, or -EINVAL with why. */
int remote_topic_check(const char *topic, char *why, size_t n);

/* What is shown, as the state topic says it (JSON, retained). */
struct remote_state {
	const char *model;  /* the file's name (no folder); NULL: the built-in */
	const char *matcap; /* the same */
	int stop;	    /* 1-based; 0: none */
	bool screen_on;
	const char *error; /* the last error in the journal; "" or NULL: none */
};

/* A leader's step for its followers ([mqtt] sync): what it shows, and the
 * wall clock (CLOCK_REALTIME, ms) it shows it from; the followers show
 * the same from then. Indices as the app state has them. The payload:
 * "at=MS model=M matcap=C stop=S", these keys in this order. */
struct remote_sync {
	unsigned long long at_ms;
	int model;  /* -1..9999; -1: no list */
	int matcap; /* 0..998 */
	int stop;   /* -1..63; -1: none */
};

#define REMOTE_SYNC_MAX 80

/* 0, or -EINVAL with what was expected in why. */
int remote_sync_parse(const void *payload, size_t len, struct remote_sync *s, char *why, size_t n);
/* The payload of s into buf (REMOTE_SYNC_MAX bytes at least); its length. */
int remote_sync_format(const struct remote_sync *s, char *buf, size_t n);

/* The JSON of st into buf (n bytes); its length, or -ENOSPC. */
int remote_state_json(const struct remote_state *st, char *buf, size_t n);
/* The last part of a path (a model's or matcap's file name). */
const char *remote_basename(const char *path);

#endif
