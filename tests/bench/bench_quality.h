/* The speed-against-error bench (tests/bench/bench_quality.c measures,
 * tests/bench/bench_quality_report.c writes the tables and the plot's data). */
#ifndef MK_BENCH_QUALITY_H
#define MK_BENCH_QUALITY_H

#include "display/display.h"
#include "util/image.h"
#include "render/render.h"
#include "render/shading.h"

#include <stdbool.h>
#include <stdint.h>

#define MAX_SETTINGS  24
#define NOISE	      0.10 /* a setting must be 10% faster to count as faster */
#define PSNR_TIE      0.25 /* ... and 0.25 dB (6% of the squared error) more accurate */
#define OFF_TOL	      2	   /* of 255: a pixel "off" */
#define PSNR_CAP      99.0 /* the reference against itself, in the plot */
#define WARMUP	      2	   /* frames drawn and not counted, each round */
#define WARMUP_SWITCH 6	   /* ... when the display before was another */
#define ROUNDS	      3	   /* interleaved rounds over a scene's settings */
#define MAX_FRAMES    96
#define DISPLAYS      7

/* The shipped matcaps' size (matcaps/README.md); the other defaults are
 * src/config/options.c's. */
#define DEFAULT_MATCAP 256

enum model { KNOT_16K, KNOT_100K, KNOT_1M, ENGINE };
/* A real model with hard edges and UV seams (Debian's assimp-testmodels):
 * where the level of detail has to simplify across seams. */
#define ENGINE_GLB "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"

struct look {
	const char *name;
	enum model model;
	enum shading_mode mode, cheaper; /* the default, and the cheaper variant */
	bool iridescence, detail, lit;
	int small; /* drawn in small x small pixels of the frame; 0: all of it */
};

/* The scenes, in the report's order. */
#define LOOKS 10
extern const struct look looks[LOOKS];

struct setting {
	char label[40];
	enum shading_mode mode;
	bool highp, is_default, is_reference;
	enum matcap_filter filter; /* the matcap's (renderer_set_matcap_filter) */
	bool mipmapped;		   /* what the filter reads here (matcap_filter_mipmaps) */
	enum vertex_format format; /* renderer_set_vertex_format */
	long vertex_bytes;	   /* measured: renderer_get_stats */
	double lod;
	int matcap, ss;
	/* EGL headless: 1 without multisampling, else the samples per pixel;
	 * 0: the bench's own backend */
	int msaa;
	/* measured */
	int same_as; /* an earlier setting that drew exactly this, or -1 */
	uint32_t triangles;
	double times[MAX_FRAMES];
	int timed;
	double ms, p90, psnr, off;
	bool front;
};

struct bench {
	const char *out, *scratch;
	int width, height, frames;
	bool egl;
	/* 1x, 2x, 4x; then EGL headless at 1x, plain and multisampled with 2,
	 * 4 and 8 samples asked (NULL where there is none) */
	struct display *display[DISPLAYS];
	struct renderer *renderer[DISPLAYS];
	struct image matcap[5];
	char detail_path[512];
	struct setting settings[LOOKS][MAX_SETTINGS];
	int count[LOOKS];
	double lod_default;
	bool highp_default; /* the renderer's own choice for this GL */
	enum matcap_filter filter_default;
	enum vertex_format format_default;
	const char *only; /* run only the scenes whose name has this; NULL: all */
	char load[2][64]; /* /proc/loadavg at the start and the end */
	int last_display; /* the one measure() drew with last */
};

/* Frames per round for b->frames in all. */
int bench_rounds_frames(const struct bench *b);
/* OUTDIR/speed-error.md, .dat and -front.dat. Returns 0 or -EIO. */
int bench_write_report(struct bench *b);

#endif
