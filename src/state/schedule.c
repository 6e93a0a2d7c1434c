#include "state/schedule.h"

#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <strings.h>

/* In the order of tm_wday. */
static const char *const day_names[7] = {"Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat"};

struct cursor {
	const char *p, *text;
	char *err;
	size_t err_size;
};

static int fail(struct cursor *c, const char *expected)
{
	int len = 0;

	while (c->p[len] && c->p[len] != ',' && len < 24)
		len++;
	if (*c->p)
		snprintf(c->err, c->err_size, "at \"%.*s\" (column %d): expected %s", len, c->p,
			 (int)(c->p - c->text) + 1, expected);
	else
		snprintf(c->err, c->err_size, "at the end: expected %s", expected);
	return -EINVAL;
}

static void skip_spaces(struct cursor *c)
{
	while (*c->p == ' ' || *c->p == '\t')
		c->p++;
}

static int day(struct cursor *c)
{
	for (int d = 0; d < 7; d++)
		if (!strncasecmp(c->p, day_names[d], 3) && !isalpha((unsigned char)c->p[3])) {
			c->p += 3;
			return d;
		}
	return -1;
}

/* "Mon", "Mon-Fri", "Sat-Mon" (through the week's end) or "daily". */
static int days(struct cursor *c, unsigned *mask)
{
	int first, last;

	if (!strncasecmp(c->p, "daily", 5) && !isalpha((unsigned char)c->p[5])) {
		c->p += 5;
		*mask = 0x7f;
		return 0;
	}
	first = last = day(c);
	if (first < 0)
		return fail(c, "a weekday (Mon, Tue, Wed, Thu, Fri, Sat, Sun) or daily");
	if (*c->p == '-') {
		c->p++;
		last = day(c);
		if (last < 0)
			return fail(c, "the weekday that ends the range (Mon-Fri)");
	}
	*mask = 0;
	for (int d = first;; d = (d + 1) % 7) {
		*mask |= 1u << d;
		if (d == last)
			break;
	}
	return 0;
}

static int two_digits(struct cursor *c, int *out)
{
	if (!isdigit((unsigned char)c->p[0]) || !isdigit((unsigned char)c->p[1]))
		return -1;
	*out = (c->p[0] - '0') * 10 + (c->p[1] - '0');
	c->p += 2;
	return 0;
}

/* HH:MM, 00:00 to 24:00. */
static int clock_time(struct cursor *c, int *minutes)
{
	const char *start = c->p;
	int h, m;

	if (two_digits(c, &h) || *c->p++ != ':' || two_digits(c, &m) || h > 24 || m > 59 ||
	    (h == 24 && m)) {
		c->p = start;
		return fail(c, "a time HH:MM from 00:00 to 24:00");
	}
	*minutes = h * 60 + m;
	return 0;
}

static int span(struct cursor *c, unsigned mask, struct schedule *s)
{
	const char *start = c->p;
	struct schedule_span sp = {.days = mask};

	if (clock_time(c, &sp.start))
		return -EINVAL;
	if (*c->p != '-')
		return fail(c, "'-' and the time the span ends (08:00-20:00)");
	c->p++;
	if (clock_time(c, &sp.end))
		return -EINVAL;
	if (sp.start == sp.end || (sp.start == 24 * 60)) {
		c->p = start;
		return fail(c, "a span that is not empty (08:00-20:00)");
	}
	if (sp.end == 24 * 60)
		sp.end = 0; /* to midnight: past midnight by nothing */
	if (s->count == SCHEDULE_MAX_SPANS) {
		c->p = start;
		return fail(c, "at most 32 spans in all");
	}
	s->spans[s->count++] = sp;
	return 0;
}

static int entry(struct cursor *c, struct schedule *s)
{
	unsigned mask = 0;
	int n = 0;

	skip_spaces(c);
	if (days(c, &mask))
		return -EINVAL;
	for (;;) {
		skip_spaces(c);
		if (!*c->p || *c->p == ',')
			break;
		if (span(c, mask, s))
			return -EINVAL;
		n++;
	}
	return n ? 0 : fail(c, "a span after the days (Mon-Fri 08:00-20:00)");
}

int schedule_parse(struct schedule *s, const char *text, char *err, size_t err_size)
{
	struct cursor c = {.p = text, .text = text, .err = err, .err_size = err_size};

	memset(s, 0, sizeof(*s));
	for (;;) {
		if (entry(&c, s)) {
			memset(s, 0, sizeof(*s));
			return -EINVAL;
		}
		if (!*c.p)
			return 0;
		c.p++; /* the comma */
	}
}

static bool span_on(const struct schedule_span *sp, int wday, int minute)
{
	int yesterday = (wday + 6) % 7;

	if (sp->end > sp->start)
		return (sp->days >> wday & 1) && minute >= sp->start && minute < sp->end;
	/* Past midnight: the evening of its day, the morning of the next. */
	return ((sp->days >> wday & 1) && minute >= sp->start) ||
	       ((sp->days >> yesterday & 1) && minute < sp->end);
}

bool schedule_on(const struct schedule *s, int wday, int minute)
{
	if (!s->count)
		return true;
	for (int i = 0; i < s->count; i++)
		if (span_on(&s->spans[i], wday, minute))
			return true;
	return false;
}
