/* [scene] in kiosk.ini, with [display] rotation and background, and
 * [material]: what is shown, and how it is seen. Plain data, so that the settings need not
 * know the content pipeline (src/content/) that reads it. */
#ifndef MK_CONTENT_CONFIG_H
#define MK_CONTENT_CONFIG_H

#include "config/lang_text.h"
#include "render/shading.h"
#include "render/wall.h"
#include "scene/text/caption.h"
#include "scene/mesh/material.h"
#include "state/hotspot.h"
#include "state/view.h"

#include <stdbool.h>

/* [scene] fit when it is not set: the model fills most of the frame and
 * leaves it a margin. */
#define CONTENT_FIT_DEFAULT 0.85

/* Room for a bit per setting of the table (settings.h checks it). */
#define CONTENT_CLI_BYTES 32

struct content_config {
	char *model;	    /* a file, folder or list (model_list.h); NULL: the built-in knot */
	char *model_scene;  /* the glTF scene by index or name; NULL: the file's */
	char *animation;    /* the glTF clip(s) --time poses; NULL: auto (the first) */
	char *variant;	    /* KHR_materials_variants variant shown first; NULL: the defaults */
	int anim_loop;	    /* enum anim_loop */
	double anim_speed;  /* the clip's speed */
	double anim_time;   /* --time: seconds into the clip; < 0: the rest pose */
	char *matcap;	    /* a file or a folder; NULL: the shipped folder */
	char *matcap_first; /* the folder's matcap shown first; NULL: see load_matcap */
	char *background;   /* render/background.h's text; NULL: the default */
	double fit;	    /* render/framing.h: the share of the frame the model fills */
	double zoom;	    /* --zoom: this scale instead of the fit's; 0: the fit's */
	enum shading_mode mode;
	bool ortho;
	double yaw, pitch; /* degrees, the resting orientation */
	double lod_pixels; /* simplify to this error on the display; 0: off */
	int normals;	   /* [scene] normals: enum mesh_normals (0: file) */
	/* [scene] texture_memory: MiB the model's decoded textures share; 0:
	 * auto (scene/texture.h) */
	double texture_memory;
	/* [kiosk] prepare_threads: the level of detail's threads; 0: auto
	 * (one a core, scene/mesh/lod_split.h) */
	int prepare_threads;
	int rotation;		 /* the panel's, degrees */
	struct wall_layout wall; /* [wall]: this screen's slice of a wall; 1x1: none */
	struct material_config material;
	struct frame_config frame;     /* [frame]: orientation, start view, limits, stops */
	struct caption_config caption; /* [caption] */
	struct lang_texts texts;       /* every KEY[LANG] = text of the files read */
	char
	    *lang; /* --lang: the language shown (a code of [caption] languages); NULL: the first */
	/* [hotspot.NAME] sections: kiosk.ini's, then the model's own over
	 * them (config/hotspot_settings.h); fixed arrays, copied whole. */
	struct hotspot_set hotspots;
	/* Live playback: anim_live is set for the live kiosk (not a
	 * setting); [scene] animation_fps (0: the display's rate) and
	 * animation_pause_after (seconds without input; 0: never). */
	bool anim_live;
	/* --check-config (not a setting): a clip the model lacks fails the
	 * load, as --time's does, and the cache is passed by (its entry
	 * for such a model is a still's and says nothing of the clip). */
	bool anim_strict;
	/* The live kiosk (not a setting): each model loaded is named in the
	 * state folder first, so that one that kills the process is passed
	 * over after the restart (content/load_guard.h). */
	bool crash_memory;
	/* The live kiosk (not a setting): a large model prepared from scratch
	 * is shown coarse first (content/content_coarse.c); [kiosk]
	 * coarse_above: above how many triangles (0: never). A still never. */
	bool coarse_first;
	int coarse_above;
	double anim_fps;
	double anim_pause_after;
	/* Which of the table's settings the command line set (bit i:
	 * option_defs[i]): a model's NAME.ini does not override them
	 * (content_config_keep_cli). Plain bits, so that a copy carries them. */
	unsigned char from_cli[CONTENT_CLI_BYTES];
};

#endif
