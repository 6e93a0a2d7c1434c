/* --status: what a running kiosk shows, for remote support over SSH or a
 * monitoring script. The kiosk listens on a unix socket in its runtime
 * folder ($RUNTIME_DIRECTORY, systemd's RuntimeDirectory=, else
 * /run/matcap-kiosk); a client that connects is the request. The kiosk
 * then writes the frame on screen (frame.png) and its state (state.json)
 * there, sends the same JSON down the socket and hangs up. Nothing is
 * done per frame: the frame is read back only when asked. */
#ifndef MK_STATUS_H
#define MK_STATUS_H

#include "state/visits.h"
#include "util/image.h"

#include <stdbool.h>
#include <stdio.h>

/* What happened since the start, counted where it happens (the metrics,
 * src/app/metrics.h, report them). */
struct status_counts {
	long reloads, reload_failures; /* SIGHUP: done, or the scene kept */
	long model_loads,
	    model_load_failures; /* a model of the folder or list swapped in, or not */
};

/* What state.json says (and the metrics, with the rest). */
struct status_report {
	const char *model;  /* NULL: the built-in knot */
	const char *matcap; /* the image shown; NULL: the built-in clay */
	const char *mode;
	double view[4]; /* the model's orientation, a quaternion x, y, z, w */
	bool screen_on;
	bool camera_on;
	double uptime_s;
	long frames_drawn;
	const char *last_error; /* "" when none */
	double last_error_at;	/* seconds since the epoch; 0: none */
	double started_at;	/* seconds since the epoch */
	struct status_counts counts;
	const struct visits *visits; /* what visitors did; NULL: nothing */
};

struct status_server;

/* Listening in the runtime folder; NULL (logged) when there is no such
 * folder or another kiosk answers there already. */
struct status_server *status_server_new(void);
void status_server_free(struct status_server *s);
/* For poll(); -1 for NULL. */
int status_server_fd(const struct status_server *s);
/* A client waits (the fd was readable): take it. Returns true when there
 * is one to answer. */
bool status_server_accept(struct status_server *s);
/* Whether a frame should be read back for this answer: at most one a
 * second; in between the answer names the last one written. */
bool status_server_wants_frame(const struct status_server *s);
/* Answer the client taken: the JSON composed here, the PNG encoded and
 * the files and the socket written on a thread of the server's (the loop
 * thread only read the frame back). The frame's pixels are taken (frame
 * is left empty); NULL: none read. */
void status_server_answer(struct status_server *s, const struct status_report *r,
			  struct image *frame);
/* The client: ask the running kiosk and print its answer to out.
 * Returns 0, or 1 after saying why on stderr. */
int status_client_run(FILE *out);

#endif
