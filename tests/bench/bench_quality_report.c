/* The speed-against-error report: the tables (OUTDIR/speed-error.md) and
 * the plot's data (speed-error.dat, -front.dat) from what
 * tests/bench/bench_quality.c measured, and the binary16 mirror's errors. */
#include "bench_quality.h"
#include "oracle/oracle.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

static void describe_machine(FILE *f, const struct bench *b)
{
	struct utsname u;
	char line[256], cpu[256] = "unknown CPU";
	FILE *info = fopen("/proc/cpuinfo", "r");
	time_t t = time(NULL);
	const struct gl *gl = &b->display[0]->gl;

	while (info && fgets(line, sizeof(line), info))
		if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
			snprintf(cpu, sizeof(cpu), "%s", strchr(line, ':') + 2);
			cpu[strcspn(cpu, "\n")] = '\0';
			break;
		}
	if (info)
		fclose(info);
	uname(&u);
	b->display[0]->begin_frame(b->display[0]);
	fprintf(f,
		"Measured on %s %s, %s, %ld cores; %s through %s (%s), %s; load average "
		"%s at the start, %s at the end (other work on the machine slows every row "
		"alike, roughly).\n\n",
		u.sysname, u.machine, cpu, sysconf(_SC_NPROCESSORS_ONLN),
		(const char *)gl->GetString(GL_RENDERER), b->display[0]->name,
		(const char *)gl->GetString(GL_VERSION), strtok(ctime(&t), "\n"), b->load[0],
		b->load[1]);
}

static void describe_method(FILE *f, const struct bench *b)
{
	char msaa_note[200] = "here no EGL headless display had multisampling: no such rows";
	static const int asked[] = {2, 4, 8};
	size_t len = 0;

	for (int k = 4; k < DISPLAYS; k++) {
		const struct display *d = b->display[k];

		if (!d)
			continue;
		if (!len) {
			d->begin_frame((struct display *)d);
			len = (size_t)snprintf(msaa_note, sizeof(msaa_note), "here %.60s gave",
					       (const char *)d->gl.GetString(GL_RENDERER));
		}
		if (len < sizeof(msaa_note))
			len += (size_t)snprintf(msaa_note + len, sizeof(msaa_note) - len,
						" %d for %d,", d->samples, asked[k - 4]);
	}
	if (len && len < sizeof(msaa_note))
		snprintf(msaa_note + len - 1, sizeof(msaa_note) - len + 1,
			 " (a row per count given)");
	fprintf(f,
		"Each scene is drawn at %dx%d from the kiosk's resting view (yaw -30, pitch "
		"20) with the defaults\n(%s, level of detail %g px, a %d matcap, no "
		"supersampling), then with one setting changed\nat a time. highp is the "
		"default here because src/render/render.c takes it on a CPU rasteriser, which\n"
		"emulates 16-bit mediump (the mediump rows show the cost); on a GPU the "
		"default is mediump,\nwith highp only where the C mirror shows it is needed "
		"(the last table).\n\n"
		"Time: the median (and 90th percentile) of %d frames, each finished "
		"(glFinish), drawn in %d\nrounds over the scene's settings so that the "
		"machine's load falls on all alike, each after\n%d frames that are not "
		"counted (%d after a change of frame size). A setting that draws\nexactly "
		"what an earlier one drew (a level of detail that leaves the model whole) "
		"takes its\nfigures (\"as ...\").\n\n"
		"Error: against the reference (every float highp, no simplification, a 1024 "
		"matcap, 4x4\nsupersampling, and the scene's accurate mode: view, or "
		"sem-fragment), over the pixels where\neither image shows the model: PSNR, "
		"and the share of pixels off by more than %d/255 in a\nchannel. "
		"Supersampling is drawn at 2x or 4x the size and box-filtered on the CPU; "
		"the time\nleaves the filter out. The \"antialias N (msaa)\" rows are [display] "
		"antialias: the same scene\non an EGL headless display multisampled with N "
		"samples (OSMesa has none), resolved by\nthe GPU within the time, against "
		"\"egl-headless, antialias off\" for their cost (another\ncontext than OSMesa's, "
		"and 32-bit indices where OSMesa has none); %s. The matcap "
		"is the gold\none, baked at each size. The reference's matcap is "
		"mipmapped: at 4x a 1024 matcap is still\nminified several texels a sample on a "
		"thin part, and unfiltered it aliases too; its vertices are\nfloat32. A scene "
		"named \"128 px\" draws the model in a 128x128 corner of the frame: small on\n"
		"screen. \"vertex MB\": the vertex arrays uploaded (renderer_get_stats).\n\n"
		"Front: a setting is on it when no other is as accurate (within %.2f dB) and "
		"%d%% faster, or\nmore accurate and as fast (within %d%%): differences "
		"inside the noise decide nothing.\n\n",
		b->width, b->height, b->highp_default ? "highp" : "mediump", b->lod_default,
		DEFAULT_MATCAP, bench_rounds_frames(b) * ROUNDS, ROUNDS, WARMUP, WARMUP_SWITCH,
		OFF_TOL, msaa_note, PSNR_TIE, (int)(NOISE * 100), (int)(NOISE * 100));
}

static void write_table(FILE *f, const struct look *lk, const struct setting *s, int n)
{
	fprintf(f,
		"### %s\n\n| setting | triangles | vertex MB | median ms | p90 ms | PSNR dB | "
		"off > %d/255 | front |\n|---|---|---|---|---|---|---|---|\n",
		lk->name, OFF_TOL);
	for (int i = 0; i < n; i++) {
		const char *bold = s[i].is_default ? "**" : "";
		char psnr[16];

		if (isinf(s[i].psnr))
			snprintf(psnr, sizeof(psnr), "-");
		else
			snprintf(psnr, sizeof(psnr), "%.1f", s[i].psnr);
		if (s[i].same_as >= 0) {
			fprintf(f, "| %s%s%s | %u | %.2f | as %s | | | | %s |\n", bold, s[i].label,
				bold, s[i].triangles, s[i].vertex_bytes / 1e6,
				s[s[i].same_as].label, s[i].front ? "yes" : "");
			continue;
		}
		fprintf(f, "| %s%s%s | %u | %.2f | %.1f | %.1f | %s | %.2f%% | %s |\n", bold,
			s[i].label, bold, s[i].triangles, s[i].vertex_bytes / 1e6, s[i].ms,
			s[i].p90, psnr, 100.0 * s[i].off, s[i].front ? "yes" : "");
	}
	fprintf(f, "\n");
}

/* |r + z| < 0.03: the SEM singularity's neighbourhood, where only the
 * uv's radius is defined (tests/unit/test_stability.c). */
static bool sem_band(const double n[3], const double e[3])
{
	double d = n[0] * e[0] + n[1] * e[1] + n[2] * e[2];

	return hypot(hypot(e[0] - 2 * d * n[0], e[1] - 2 * d * n[1]), e[2] - 2 * d * n[2] + 1) <
	       0.03;
}

static void grey(const void *texture, double u, double v, double rgba[4])
{
	(void)texture, (void)u, (void)v;
	rgba[0] = rgba[1] = rgba[2] = 0.5, rgba[3] = 1.0;
}

/* The worst fp16 mirror error over pixels of a sphere: uv, in texels of
 * a 256 matcap, for a mapping mode; colour, in 1/255, for a feature. */
static double sphere_error(int mode, enum shading_fp fp)
{
	double dist = 1.08 / sin(15.0 * M_PI / 180.0), worst = 0.0;

	for (int i = 0; i < 200; i++)
		for (int j = 0; j < 200; j++) {
			double x = (i + 0.5) / 100.0 - 1.0, y = (j + 0.5) / 100.0 - 1.0;
			double n[3] = {x, y, sqrt(fmax(0.0, 1.0 - x * x - y * y))};
			double e[3] = {x, y, n[2] - dist}, a[3], c[3];
			struct shading_fragment f = {.mode = SHADING_VIEW,
						     .iridescence = mode == 3,
						     .lit = mode == 4,
						     .iridescence_uniform = {0.4, 0.33, 0.2, 1.0},
						     .hsv = {0.7, 0.8},
						     .light = {-0.5499, 0.6198, 0.5599},
						     .base_color = {0.8, 0.8, 0.8},
						     .shininess = 48,
						     .sample = grey};

			if (x * x + y * y > 0.998)
				continue;
			if (mode < 3) {
				/* as the fragment stage: both varyings normalized first */
				double nd[3], ed[3], nf[3], ef[3];

				shading_safe_normalize(n, nd), shading_safe_normalize(e, ed);
				shading_safe_normalize_f(fp, n, nf),
				    shading_safe_normalize_f(fp, e, ef);
				if (mode == 2 && sem_band(nd, ed))
					continue;
				if (mode == 0)
					shading_uv_normal(nd, a), shading_uv_normal_f(fp, nf, c);
				else if (mode == 1)
					shading_uv_view(nd, ed, a),
					    shading_uv_view_f(fp, nf, ef, c);
				else
					shading_uv_sem(nd, ed, a), shading_uv_sem_f(fp, nf, ef, c);
				worst = fmax(worst, hypot(a[0] - c[0], a[1] - c[1]) * 256.0);
				continue;
			}
			memcpy(f.normal, n, sizeof(n));
			memcpy(f.eye, e, sizeof(e));
			shading_fragment(&f, a);
			shading_fragment_f(fp, &f, c);
			for (int k = 0; k < 3; k++)
				worst = fmax(worst, fabs(a[k] - c[k]) * 255.0);
		}
	return worst;
}

static void write_precision(FILE *f)
{
	static const char *const what[] = {"normal (uv, texels of 256)", "view (uv, texels of 256)",
					   "sem, off the singular band (uv, texels of 256)",
					   "iridescence (colour, /255)",
					   "lit, shininess 48 (colour, /255)"};

	fprintf(
	    f,
	    "### Precision on a GPU with 16-bit mediump\n\nllvmpipe runs mediump "
	    "partly in 16 bits, which the rows above measure; a Mali or\nAdreno runs "
	    "all of it so. The C mirror, rounded to binary16 after every operation\n"
	    "(tests/oracle/fp16.c), on a sphere's pixels; the shipped shaders make highp only what "
	    "needs it:\n\n| value | binary32 | binary16 + highp (shipped) | binary16 "
	    "(no highp) |\n|---|---|---|---|\n");
	for (int m = 0; m < 5; m++)
		fprintf(f, "| %s | %.3f | %.2f | %.2f |\n", what[m], sphere_error(m, SHADING_FP32),
			sphere_error(m, SHADING_FP16_HIGHP), sphere_error(m, SHADING_FP16));
	fprintf(f, "\n");
}

static void write_data(FILE *dat, FILE *front, const struct setting *s, int n)
{
	int order[MAX_SETTINGS], count = 0;

	for (int i = 0; i < n; i++)
		if (s[i].same_as < 0)
			fprintf(dat, "%.3f %.3f %d %d %d \"%s\"\n", s[i].ms,
				isinf(s[i].psnr) ? PSNR_CAP : s[i].psnr, s[i].front,
				s[i].is_default, s[i].is_reference, s[i].label);
	for (int i = 0; i < n; i++)
		if (s[i].front && !s[i].is_reference && s[i].same_as < 0)
			order[count++] = i;
	/* By time, for the line that joins them. */
	for (int i = 1; i < count; i++)
		for (int j = i; j > 0 && s[order[j]].ms < s[order[j - 1]].ms; j--) {
			int t = order[j];

			order[j] = order[j - 1], order[j - 1] = t;
		}
	for (int i = 0; i < count; i++)
		fprintf(front, "%.3f %.3f\n", s[order[i]].ms,
			isinf(s[order[i]].psnr) ? PSNR_CAP : s[order[i]].psnr);
	fprintf(dat, "\n\n");
	fprintf(front, "\n\n");
}

static FILE *open_out(const struct bench *b, const char *name)
{
	char path[600];
	FILE *f;

	snprintf(path, sizeof(path), "%s/%s", b->out, name);
	f = fopen(path, "w");
	if (!f)
		fprintf(stderr, "%s: %s\n", path, strerror(errno));
	return f;
}

int bench_write_report(struct bench *b)
{
	FILE *md = open_out(b, "speed-error.md"), *dat = open_out(b, "speed-error.dat");
	FILE *front = open_out(b, "speed-error-front.dat");
	int ret = md && dat && front ? 0 : -EIO;

	if (!ret) {
		fprintf(md, "## Speed against error\n\n");
		describe_machine(md, b);
		describe_method(md, b);
		fprintf(md, "Defaults on the front:");
		for (size_t l = 0; l < LOOKS; l++)
			for (int i = 0; i < b->count[l]; i++)
				if (b->settings[l][i].is_default)
					fprintf(md, "%s %s: %s", l ? ";" : "", looks[l].name,
						b->settings[l][i].front ? "yes" : "NO");
		fprintf(md, ".\n\n");
		for (size_t l = 0; l < LOOKS; l++) {
			if (!b->count[l])
				continue; /* left out (--only) */
			write_table(md, &looks[l], b->settings[l], b->count[l]);
			write_data(dat, front, b->settings[l], b->count[l]);
			fprintf(dat, "# %s\n", looks[l].name);
		}
		write_precision(md);
	}
	if (md)
		fclose(md);
	if (dat)
		fclose(dat);
	if (front)
		fclose(front);
	return ret;
}
