/* Remote control's words: see remote.h. Every byte of a payload is
 * checked before a word is looked at, so what reaches the loop is one of
 * a few commands with a bounded number, never a name the kiosk would
 * open. */
#include "state/remote.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const verb_names[] = {"model",    "matcap", "stop",	 "variant",
					 "language", "screen", "reload", NULL};

/* What each verb takes, for the reason a payload was refused. */
static const char *const verb_args[] = {
    "'model next' or 'model prev'",
    "'matcap next', 'matcap prev' or 'matcap N' (1-999, the folder's Nth by name)",
    "'stop next', 'stop prev' or 'stop N' (1-64, [frame] stops' Nth)",
    "'variant next'",
    "'language TAG' (a BCP 47 tag such as de or pt-BR)",
    "'screen on' or 'screen off'",
    "'reload' alone",
};

#define COMMANDS "model, matcap, stop, variant, language, screen or reload"

static int refuse(char *why, size_t n, const char *fmt, const char *what)
{
	snprintf(why, n, fmt, what);
	return -EINVAL;
}

/* Printable ASCII only, no tab: a control byte, a NUL or UTF-8 is refused
 * before anything else is read. A trailing newline (mosquitto_pub -l) is
 * not part of the command. */
static int copy_payload(const void *payload, size_t len, char *text, char *why, size_t n)
{
	const unsigned char *p = payload;

	while (len && (p[len - 1] == '\n' || p[len - 1] == '\r'))
		len--;
	if (!len)
		return refuse(why, n, "an empty payload: expected %s", COMMANDS);
	if (len > REMOTE_PAYLOAD_MAX)
		return refuse(why, n, "longer than %s bytes", "64");
	for (size_t i = 0; i < len; i++) {
		if (p[i] < 0x20 || p[i] > 0x7e) {
			snprintf(why, n, "byte %zu is 0x%02x: expected printable ASCII", i + 1,
				 p[i]);
			return -EINVAL;
		}
	}
	memcpy(text, p, len);
	text[len] = '\0';
	return 0;
}

/* 1..max in decimal, no sign, no leading zero. */
static int number(const char *s, int max)
{
	long v = 0;

	if (!*s || *s == '0' || strlen(s) > 3)
		return 0;
	for (; *s; s++) {
		if (*s < '0' || *s > '9')
			return 0;
		v = v * 10 + (*s - '0');
	}
	return v <= max ? (int)v : 0;
}

/* A BCP 47 tag as kiosks use it: 2-3 lowercase letters, optionally '-'
 * and a region (2 uppercase letters or 3 digits) or script (4 letters). */
static bool language_tag(const char *s)
{
	size_t lang = strspn(s, "abcdefghijklmnopqrstuvwxyz");
	const char *sub = s + lang;
	size_t k;

	if (lang < 2 || lang > 3)
		return false;
	if (!*sub)
		return true;
	if (*sub++ != '-')
		return false;
	k = strlen(sub);
	if (k == 2)
		return strspn(sub, "ABCDEFGHIJKLMNOPQRSTUVWXYZ") == 2;
	if (k == 3)
		return strspn(sub, "0123456789") == 3;
	return k == 4 && strspn(sub, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz") == 4;
}

static bool step_word(const char *arg, struct remote_cmd *cmd)
{
	if (!strcmp(arg, "next"))
		cmd->step = 1;
	else if (!strcmp(arg, "prev"))
		cmd->step = -1;
	return cmd->step != 0;
}

/* The argument of a known verb; false when it is not one it takes. */
static bool argument(struct remote_cmd *cmd, const char *arg)
{
	switch (cmd->verb) {
	case REMOTE_MODEL:
		return arg && step_word(arg, cmd);
	case REMOTE_MATCAP:
		return arg &&
		       (step_word(arg, cmd) || (cmd->index = number(arg, REMOTE_MATCAP_MAX)));
	case REMOTE_STOP:
		return arg && (step_word(arg, cmd) || (cmd->index = number(arg, REMOTE_STOP_MAX)));
	case REMOTE_VARIANT:
		return arg && step_word(arg, cmd) && cmd->step == 1;
	case REMOTE_LANGUAGE:
		if (!arg || strlen(arg) >= sizeof(cmd->language) || !language_tag(arg))
			return false;
		strcpy(cmd->language, arg);
		return true;
	case REMOTE_SCREEN:
		cmd->on = arg && !strcmp(arg, "on");
		return arg && (cmd->on || !strcmp(arg, "off"));
	case REMOTE_RELOAD:
		return !arg;
	}
	return false;
}

int remote_parse(const void *payload, size_t len, struct remote_cmd *cmd, char *why, size_t n)
{
	char text[REMOTE_PAYLOAD_MAX + 1];
	char *arg;
	int v;

	memset(cmd, 0, sizeof(*cmd));
	if (copy_payload(payload, len, text, why, n))
		return -EINVAL;
	/* One space between the verb and its argument, none elsewhere. */
	arg = strchr(text, ' ');
	if (arg)
		*arg++ = '\0';
	for (v = 0; verb_names[v] && strcmp(verb_names[v], text); v++)
		;
	if (!verb_names[v])
		return refuse(why, n, "'%.20s' is no command: expected " COMMANDS, text);
	if (arg && strchr(arg, ' '))
		return refuse(why, n, "'%s ...': one word after the command at most", text);
	cmd->verb = (enum remote_verb)v;
	if (!argument(cmd, arg))
		return refuse(why, n, "expected %s", verb_args[v]);
	return 0;
}

void remote_describe(const struct remote_cmd *cmd, char *buf, size_t n)
{
	const char *verb = verb_names[cmd->verb];

	if (cmd->verb == REMOTE_LANGUAGE)
		snprintf(buf, n, "%s %s", verb, cmd->language);
	else if (cmd->verb == REMOTE_SCREEN)
		snprintf(buf, n, "%s %s", verb, cmd->on ? "on" : "off");
	else if (cmd->verb == REMOTE_RELOAD)
		snprintf(buf, n, "%s", verb);
	else if (cmd->index)
		snprintf(buf, n, "%s %d", verb, cmd->index);
	else
		snprintf(buf, n, "%s %s", verb, cmd->step > 0 ? "next" : "prev");
}

int remote_broker_parse(const char *text, char *host, size_t host_n, int *port, int default_port,
			char *why, size_t n)
{
	size_t len =
	    strspn(text, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.-");
	const char *colon = text + len;
	long p = default_port;
	char *end;

	if (!len || len >= host_n || len > REMOTE_HOST_MAX || (*colon && *colon != ':')) {
		snprintf(why, n, "'%.40s': expected HOST or HOST:PORT (a name or an IPv4 address)",
			 text);
		return -EINVAL;
	}
	if (*colon) {
		errno = 0;
		p = strtol(colon + 1, &end, 10);
		if (colon[1] < '1' || colon[1] > '9' || *end || errno || p > 65535) {
			snprintf(why, n, "'%.40s': the port must be a number 1-65535", text);
			return -EINVAL;
		}
	}
	memcpy(host, text, len);
	host[len] = '\0';
	*port = (int)p;
	return 0;
}

int remote_topic_check(const char *topic, char *why, size_t n)
{
	size_t len = strlen(topic);
	const char *ok = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./";

	if (!len || len > REMOTE_TOPIC_MAX || strspn(topic, ok) != len || topic[0] == '/' ||
	    topic[len - 1] == '/' || strstr(topic, "//")) {
		snprintf(why, n,
			 "'%.40s': expected levels of letters, digits, '-', '_' and '.' joined "
			 "by '/' (at most %d bytes, no wildcard, no empty level)",
			 topic, REMOTE_TOPIC_MAX);
		return -EINVAL;
	}
	return 0;
}

const char *remote_basename(const char *path)
{
	const char *slash = path ? strrchr(path, '/') : NULL;

	return slash ? slash + 1 : path;
}

/* s as a JSON string (quoted; control bytes and quotes escaped) at *at;
 * false when buf is full. */
static bool json_string(char *buf, size_t n, size_t *at, const char *s)
{
	static const char hex[] = "0123456789abcdef";

	if (*at + 1 >= n)
		return false;
	buf[(*at)++] = '"';
	for (; s && *s; s++) {
		unsigned char c = (unsigned char)*s;

		if (*at + 7 >= n)
			return false;
		if (c == '"' || c == '\\') {
			buf[(*at)++] = '\\';
			buf[(*at)++] = (char)c;
		} else if (c < 0x20) {
			memcpy(buf + *at, "\\u00", 4);
			buf[*at + 4] = hex[c >> 4];
			buf[*at + 5] = hex[c & 15];
			*at += 6;
		} else {
			buf[(*at)++] = (char)c;
		}
	}
	buf[(*at)++] = '"';
	buf[*at] = '\0';
	return true;
}

/* A piece of literal text at *at; false when buf is full. */
static bool json_raw(char *buf, size_t n, size_t *at, const char *text)
{
	int w = snprintf(buf + *at, n - *at, "%s", text);

	if (w < 0 || (size_t)w >= n - *at)
		return false;
	*at += (size_t)w;
	return true;
}

int remote_state_json(const struct remote_state *st, char *buf, size_t n)
{
	char stop[48];
	size_t at = 0;
	bool ok;

	snprintf(stop, sizeof(stop), ",\"stop\":%d,\"screen\":\"%s\",\"error\":", st->stop,
		 st->screen_on ? "on" : "off");
	ok = json_raw(buf, n, &at, "{\"model\":") &&
	     json_string(buf, n, &at, st->model ? st->model : "") &&
	     json_raw(buf, n, &at, ",\"matcap\":") &&
	     json_string(buf, n, &at, st->matcap ? st->matcap : "") &&
	     json_raw(buf, n, &at, stop) && json_string(buf, n, &at, st->error) &&
	     json_raw(buf, n, &at, "}");
	return ok ? (int)at : -ENOSPC;
}

/* key=N at *p for a number lo..hi (a leading '-' only for -1): moves *p
 * past it and one space (none after the last). */
static bool sync_field(const char **p, const char *key, long long lo, long long hi, bool last,
		       long long *v)
{
	size_t k = strlen(key);
	const char *s = *p;
	char *end;

	if (strncmp(s, key, k) || s[k] != '=')
		return false;
	s += k + 1;
	if (!((*s >= '0' && *s <= '9') || (s[0] == '-' && s[1] == '1')))
		return false;
	errno = 0;
	*v = strtoll(s, &end, 10);
	if (errno || end == s || end - s > 16 || *v < lo || *v > hi || (*s == '0' && end - s > 1) ||
	    (last ? *end != '\0' : *end != ' '))
		return false;
	*p = last ? end : end + 1;
	return true;
}

int remote_sync_parse(const void *payload, size_t len, struct remote_sync *s, char *why, size_t n)
{
	char text[REMOTE_SYNC_MAX + 1];
	const char *p = text;
	long long at, model, matcap, stop;

	memset(s, 0, sizeof(*s));
	if (len > REMOTE_SYNC_MAX)
		return refuse(why, n, "longer than %s bytes", "80");
	if (copy_payload(payload, len, text, why, n))
		return -EINVAL;
	if (!sync_field(&p, "at", 1, 99999999999999LL, false, &at) ||
	    !sync_field(&p, "model", -1, 9999, false, &model) ||
	    !sync_field(&p, "matcap", 0, REMOTE_MATCAP_MAX - 1, false, &matcap) ||
	    !sync_field(&p, "stop", -1, REMOTE_STOP_MAX - 1, true, &stop))
		return refuse(why, n, "%s",
			      "expected 'at=MS model=M matcap=C stop=S' (the wall clock in ms, "
			      "model -1..9999, matcap 0..998, stop -1..63)");
	*s = (struct remote_sync){(unsigned long long)at, (int)model, (int)matcap, (int)stop};
	return 0;
}

int remote_sync_format(const struct remote_sync *s, char *buf, size_t n)
{
	return snprintf(buf, n, "at=%llu model=%d matcap=%d stop=%d", s->at_ms, s->model, s->matcap,
			s->stop);
}
