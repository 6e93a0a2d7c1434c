/* The settings table: each setting's option, [section] key, type, range
 * and help, and where it is kept in struct options; and the reload rules
 * of each section. What is done with one setting (parse, copy, compare,
 * release) is settings.c's. A new setting is one row here. */
#include "config/settings.h"

#include <stddef.h>

const struct options_section_rule options_sections[OPTIONS_SECTIONS] = {
    [OPTIONS_DISPLAY] = {"display", OPTIONS_AT_START, "rotation",
			 "at the next start (systemctl restart), but rotation at once"},
    [OPTIONS_SCENE] = {"scene", OPTIONS_LIVE, NULL, "at once"},
    [OPTIONS_KIOSK] = {"kiosk", OPTIONS_LIVE, NULL, "at once"},
    [OPTIONS_BUTTONS] = {"buttons", OPTIONS_REOPEN, NULL,
			 "at once; the buttons are opened again if this section changed"},
    [OPTIONS_KEYBOARD] = {"keyboard", OPTIONS_REOPEN, NULL,
			  "at once; the keyboards are opened again if this section changed"},
    [OPTIONS_MATERIAL] = {"material", OPTIONS_LIVE, NULL, "at once"},
    [OPTIONS_CAMERA] = {"camera", OPTIONS_REOPEN, NULL,
			"at once; the camera is started again if this section changed"},
    [OPTIONS_POWER] = {"power", OPTIONS_REOPEN, NULL,
		       "at once; the screen's power is decided again if this section changed"},
    [OPTIONS_TOUCH] = {"touch", OPTIONS_REOPEN, NULL,
		       "at once; the touchscreens are opened again if this section changed"},
    [OPTIONS_STATUS] = {"status", OPTIONS_LIVE, NULL,
			"at once; a metrics file no longer named is removed"},
    [OPTIONS_FRAME] = {"frame", OPTIONS_LIVE, NULL, "at once"},
    [OPTIONS_CAPTION] = {"caption", OPTIONS_LIVE, NULL, "at once"},
    [OPTIONS_KNOB] = {"knob", OPTIONS_REOPEN, NULL,
		      "at once; the knobs are opened again if this section changed"},
    [OPTIONS_MQTT] = {"mqtt", OPTIONS_AT_START, NULL, "at the next start (systemctl restart)"},
    [OPTIONS_WALL] = {"wall", OPTIONS_LIVE, NULL, "at once"},
};

static const char *const backend_names[] = {"auto", "kms", "osmesa", "egl-headless", NULL};
static const char *const mode_names[] = {"normal", "view", "sem-vertex", "sem-fragment", NULL};
static const char *const busy_names[] = {"wait", "exit", NULL};	  /* exit_when_busy */
static const char *const clock_names[] = {"own", "shared", NULL}; /* app.shared_clock */
static const char *const kms_api_names[] = {"auto", "atomic", "legacy", NULL};
static const char *const active_names[] = {"low", "high", NULL};
static const char *const bias_names[] = {"pull-up", "pull-down", "disable", "as-is", NULL};
static const char *const switch_names[] = {"auto", "off", "on", NULL}; /* enum material_switch */
static const char *const lit_names[] = {"off", "on", "beside", NULL};  /* enum material_lit */
static const char *const camera_names[] = {"off", "on", NULL};	       /* enum camera_feed_use */
static const char *const import_names[] = {"auto", "off", NULL};       /* enum camera_feed_import */
static const char *const normals_names[] = {"file", "flat", "smooth", NULL}; /* enum mesh_normals */
static const char *const loop_names[] = {"repeat", "once", "pingpong", NULL}; /* enum anim_loop */
static const char *const antialias_names[] = {"auto", "off", "2", "4", "8", NULL};
static const char *const base_color_names[] = {"auto", "off", NULL}; /* enum material_switch */
static const char *const unlit_names[] = {"file", "shade", NULL};    /* enum material_unlit */
static const char *const position_names[] = {
    "bottom-left", "bottom-right", "top-left", "top-right",
    "bottom",	   "top",	   NULL}; /* enum caption_position */
static const char *const drift_names[] = {"off", "on", NULL};
/* A number with a word for 0: its first choice (render_scale's auto). */
static const char *const auto_names[] = {"auto", NULL};
static const char *const up_names[] = {"+y", "-y", "+z", "-z", "+x", "-x", NULL}; /* frame_up */
static const char *const direction_names[] = {"right", "left", NULL};
static const char *const yes_no_names[] = {"no", "yes", NULL};
static const char *const sync_names[] = {"off", "leader", "follower", NULL}; /* enum mqtt_sync */

/* A field's place and size: the size tells a bool from an enum, and the
 * copy, the comparison and the release go by it. */
#define AT(f) offsetof(struct options, f), sizeof(((struct options *)0)->f)

/* A WxH setting is two ints side by side. */
_Static_assert(offsetof(struct display_config, height) ==
		   offsetof(struct display_config, width) + sizeof(int),
	       "display width, height");
_Static_assert(offsetof(struct wall_layout, row) ==
		   offsetof(struct wall_layout, column) + sizeof(int),
	       "wall column, row");
_Static_assert(offsetof(struct wall_layout, screen_h) ==
		   offsetof(struct wall_layout, screen_w) + sizeof(int),
	       "wall screen width, height");
_Static_assert(offsetof(struct camera_feed_config, height) ==
		   offsetof(struct camera_feed_config, width) + sizeof(int),
	       "camera width, height");
/* Choices other than a bool are kept through an int. */
_Static_assert(
    sizeof(enum backend_kind) == sizeof(int) && sizeof(enum shading_mode) == sizeof(int) &&
	sizeof(enum app_action) == sizeof(int) && sizeof(enum button_active) == sizeof(int) &&
	sizeof(enum button_bias) == sizeof(int) && sizeof(enum camera_feed_use) == sizeof(int) &&
	sizeof(enum camera_feed_import) == sizeof(int) &&
	sizeof(enum display_antialias) == sizeof(int) && sizeof(enum frame_up) == sizeof(int) &&
	sizeof(enum caption_position) == sizeof(int),
    "enums are ints");

const struct option_def option_defs[OPTION_DEFS] = {
    {"backend", 'b', OPTIONS_DISPLAY, "backend", K_CHOICE, AT(backend), 0, 0, 0, backend_names,
     "NAME", "auto, kms, osmesa or egl-headless; auto takes kms where there is a display output"},
    {"size", 's', OPTIONS_DISPLAY, "size", K_SIZE, AT(display.width), 16, 8192, 1, NULL, "WxH",
     "offscreen frame size"},
    {"rotate", 0, OPTIONS_DISPLAY, "rotation", K_INT, AT(content.rotation), 0, 270, 90, NULL, "DEG",
     "panel rotation: 0, 90, 180 or 270"},
    {"device", 0, OPTIONS_DISPLAY, "device", K_STRING, AT(display.device), 0, 0, 0, NULL, "PATH",
     "KMS: the DRM device (default: the first with a display)"},
    {"connector", 0, OPTIONS_DISPLAY, "connector", K_STRING, AT(display.connector), 0, 0, 0, NULL,
     "NAME", "KMS: the output, e.g. HDMI-A-1 or DSI-1 (default: the first connected)"},
    {"outputs", 0, OPTIONS_DISPLAY, "outputs", K_STRING, AT(display.outputs), 0, 0, 0, NULL,
     "NAMES",
     "KMS: several outputs of one board, e.g. 'HDMI-A-1, HDMI-A-2', or all; each shows the "
     "scene as its [output.NAME] says (default: [display] connector alone)"},
    {"display-mode", 0, OPTIONS_DISPLAY, "mode", K_STRING, AT(display.mode), 0, 0, 0, NULL,
     "WxH[@HZ]", "KMS: the mode (default: the preferred, else the largest)"},
    {"on-busy", 0, OPTIONS_DISPLAY, "on_busy", K_CHOICE, AT(display.exit_when_busy), 0, 0, 0,
     busy_names, "WHAT", "KMS: when another program holds the display: wait or exit"},
    {"kms-api", 0, OPTIONS_DISPLAY, "kms_api", K_CHOICE, AT(display.kms_api), 0, 0, 0,
     kms_api_names, "API",
     "KMS: auto (atomic where the driver has it), atomic or legacy; for testing"},
    {"model", 'm', OPTIONS_SCENE, "model", K_STRING, AT(content.model), 0, 0, 0, NULL, "PATH",
     "a .gltf or .glb model, or a folder or list (a,b) of them that take turns (default: a "
     "built-in torus knot)"},
    {"matcap", 'c', OPTIONS_SCENE, "matcap", K_STRING, AT(content.matcap), 0, 0, 0, NULL, "PATH",
     "a PNG/JPEG matcap, or a folder of them (cycled in name order)"},
    {"mode", 0, OPTIONS_SCENE, "mode", K_CHOICE, AT(content.mode), 0, 0, 0, mode_names, "MODE",
     "normal, view, sem-vertex or sem-fragment"},
    {"ortho", 0, OPTIONS_SCENE, "ortho", K_FLAG, AT(content.ortho), 0, 0, 0, NULL, NULL,
     "orthographic camera"},
    {"yaw", 0, OPTIONS_SCENE, "yaw", K_DOUBLE, AT(content.yaw), -360, 360, 0, NULL, "DEG",
     "turn the model about the vertical axis"},
    {"pitch", 0, OPTIONS_SCENE, "pitch", K_DOUBLE, AT(content.pitch), -360, 360, 0, NULL, "DEG",
     "tilt the model about the horizontal axis"},
    {"lod-pixels", 0, OPTIONS_SCENE, "lod_pixels", K_DOUBLE, AT(content.lod_pixels), 0, 64, 0, NULL,
     "PX", "draw no detail under PX pixels: simplify smaller triangles to that; 0: never"},
    {"normals", 0, OPTIONS_SCENE, "normals", K_CHOICE, AT(content.normals), 0, 0, 0, normals_names,
     "HOW",
     "file: the file's normals, flat (per face) where it gives none, as glTF requires; flat: "
     "flat everywhere; smooth: averaged where it gives none"},
    {"texture-memory", 0, OPTIONS_SCENE, "texture_memory", K_DOUBLE, AT(content.texture_memory), 8,
     65536, 1, auto_names, "MIB", "MiB the model's decoded textures share; auto: RAM/4, <= 256"},
    {"log-level", 0, OPTIONS_KIOSK, "log_level", K_LEVEL, AT(log_level), 0, 0, 0, log_level_names,
     "LEVEL", "error, warning, info or debug"},
    {"attract-after", 0, OPTIONS_KIOSK, "attract_after", K_DOUBLE, AT(app.attract_after_s), 0,
     86400, 0, NULL, "S", "seconds without input before the model turns by itself; 0: never"},
    {"attract-speed", 0, OPTIONS_KIOSK, "attract_speed", K_DEGREES, AT(app.attract_speed), 0, 360,
     0, NULL, "DEG/S", "how fast it turns by itself"},
    {"idle-seconds", 0, OPTIONS_KIOSK, "idle_seconds", K_DOUBLE, AT(app.attract_after_s), 0, 86400,
     0, NULL, "S", "another name for attract_after"},
    {"attract-fps", 0, OPTIONS_KIOSK, "attract_fps", K_DOUBLE, AT(app.attract_fps), 0, 240, 0, NULL,
     "FPS", "frames per second at most while it turns by itself; 0: the display's rate"},
    {"attract-model-seconds", 0, OPTIONS_KIOSK, "attract_model_seconds", K_DOUBLE,
     AT(app.attract_model_s), 0, 86400, 0, NULL, "S",
     "in attract mode, the next model every S seconds; 0: never"},
    {"turn-speed", 0, OPTIONS_KIOSK, "turn_speed", K_DEGREES, AT(app.turn_speed), 1, 1440, 0, NULL,
     "DEG/S", "how fast a held button or arrow key turns the model"},
    {"turn-step", 0, OPTIONS_KIOSK, "turn_step", K_DEGREES, AT(app.turn_step), 0, 90, 0, NULL,
     "DEG", "how far a short tap turns it"},
    {"prepare-threads", 0, OPTIONS_KIOSK, "prepare_threads", K_INT, AT(content.prepare_threads), 1,
     16, 1, auto_names, "N",
     "threads that simplify a new model (never the frame's); auto: one a core"},
    {"gpio-chip", 0, OPTIONS_BUTTONS, "chip", K_STRING, AT(buttons.chip), 0, 0, 0, NULL, "CHIP",
     "GPIO chip by name, path or label (default: line names on every chip)"},
    {"button-active", 0, OPTIONS_BUTTONS, "active", K_CHOICE, AT(buttons.active), 0, 0, 0,
     active_names, "LEVEL", "low (a button that pulls the line to ground) or high"},
    {"button-bias", 0, OPTIONS_BUTTONS, "bias", K_CHOICE, AT(buttons.bias), 0, 0, 0, bias_names,
     "BIAS", "pull-up, pull-down, disable or as-is"},
    {"debounce-ms", 0, OPTIONS_BUTTONS, "debounce_ms", K_INT, AT(buttons.debounce_ms), 0, 100, 1,
     NULL, "MS", "edges this close to the one before are contact bounce"},
    {"long-press-ms", 0, OPTIONS_BUTTONS, "long_press_ms", K_INT, AT(buttons.long_press_ms), 100,
     10000, 1, NULL, "MS", "a press held this long is a long press"},
    {"repeat-ms", 0, OPTIONS_BUTTONS, "repeat_ms", K_INT, AT(buttons.repeat_ms), 0, 5000, 1, NULL,
     "MS", "a held button with no long action repeats every MS (0: never)"},
    {"button-left", 0, OPTIONS_BUTTONS, "left", K_STRING, AT(buttons.buttons[0].line), 0, 0, 0,
     NULL, "LINE", "the left button's line: a name (GPIO17) or an offset; none: not wired"},
    {"left-press", 0, OPTIONS_BUTTONS, "left_press", K_CHOICE, AT(buttons.buttons[0].press), 0, 0,
     0, app_action_names, "ACT", "what a press of left does"},
    {"left-long-press", 0, OPTIONS_BUTTONS, "left_long_press", K_CHOICE,
     AT(buttons.buttons[0].long_press), 0, 0, 0, app_action_names, "ACT",
     "what a long press of left does (none: no long press)"},
    {"button-right", 0, OPTIONS_BUTTONS, "right", K_STRING, AT(buttons.buttons[1].line), 0, 0, 0,
     NULL, "LINE", "the right button's line: a name (GPIO17) or an offset; none: not wired"},
    {"right-press", 0, OPTIONS_BUTTONS, "right_press", K_CHOICE, AT(buttons.buttons[1].press), 0, 0,
     0, app_action_names, "ACT", "what a press of right does"},
    {"right-long-press", 0, OPTIONS_BUTTONS, "right_long_press", K_CHOICE,
     AT(buttons.buttons[1].long_press), 0, 0, 0, app_action_names, "ACT",
     "what a long press of right does (none: no long press)"},
    {"button-select", 0, OPTIONS_BUTTONS, "select", K_STRING, AT(buttons.buttons[2].line), 0, 0, 0,
     NULL, "LINE", "the select button's line: a name (GPIO17) or an offset; none: not wired"},
    {"select-press", 0, OPTIONS_BUTTONS, "select_press", K_CHOICE, AT(buttons.buttons[2].press), 0,
     0, 0, app_action_names, "ACT", "what a press of select does"},
    {"select-long-press", 0, OPTIONS_BUTTONS, "select_long_press", K_CHOICE,
     AT(buttons.buttons[2].long_press), 0, 0, 0, app_action_names, "ACT",
     "what a long press of select does (none: no long press)"},
    {"keyboard", 0, OPTIONS_KEYBOARD, "device", K_STRING, AT(keyboard.device), 0, 0, 0, NULL, "DEV",
     "auto (every keyboard under /dev/input), none, or one /dev/input/eventN"},
    {"iridescence", 0, OPTIONS_MATERIAL, "iridescence", K_CHOICE, AT(content.material.iridescence),
     0, 0, 0, switch_names, "WHEN",
     "hue layer from the view angle: auto (when the glTF has it), off, on"},
    {"iridescence-range", 0, OPTIONS_MATERIAL, "iridescence_range", K_DOUBLE,
     AT(content.material.hue_range), -8, 8, 0, NULL, "TURNS", "hue change from face-on to grazing"},
    {"iridescence-average", 0, OPTIONS_MATERIAL, "iridescence_average", K_DOUBLE,
     AT(content.material.hue_average), -8, 8, 0, NULL, "TURNS", "hue face-on (0 red, 1/3 green)"},
    {"iridescence-shift", 0, OPTIONS_MATERIAL, "iridescence_shift", K_DOUBLE,
     AT(content.material.hue_shift), -8, 8, 0, NULL, "TURNS",
     "hue shift where the detail map's alpha is 0"},
    {"iridescence-opacity", 0, OPTIONS_MATERIAL, "iridescence_opacity", K_DOUBLE,
     AT(content.material.opacity), 0, 1, 0, NULL, "A", "how much the hue layer covers the matcap"},
    {"iridescence-saturation", 0, OPTIONS_MATERIAL, "iridescence_saturation", K_DOUBLE,
     AT(content.material.saturation), 0, 1, 0, NULL, "S", "the hue layer's HSV saturation"},
    {"iridescence-value", 0, OPTIONS_MATERIAL, "iridescence_value", K_DOUBLE,
     AT(content.material.value), 0, 1, 0, NULL, "V", "the hue layer's HSV value"},
    {"iridescence-ramp", 0, OPTIONS_MATERIAL, "iridescence_ramp", K_STRING,
     AT(content.material.ramp), 0, 0, 0, NULL, "FILE",
     "a PNG/JPEG colour ramp to use instead of HSV"},
    {"detail", 0, OPTIONS_MATERIAL, "detail", K_CHOICE, AT(content.material.detail), 0, 0, 0,
     switch_names, "WHEN", "detail map: auto (when one is given), off, on"},
    {"detail-map", 0, OPTIONS_MATERIAL, "detail_map", K_STRING, AT(content.material.detail_map), 0,
     0, 0, NULL, "FILE", "packed map: normal xy (rg), occlusion (b), hue shift (a)"},
    {"displacement-map", 0, OPTIONS_MATERIAL, "displacement_map", K_STRING,
     AT(content.material.height_map), 0, 0, 0, NULL, "FILE",
     "a height map: subdivide and displace the model"},
    {"displacement-scale", 0, OPTIONS_MATERIAL, "displacement_scale", K_DOUBLE,
     AT(content.material.displacement_scale), 0, 1, 0, NULL, "R",
     "height of white, in model radii"},
    {"displacement-pixels", 0, OPTIONS_MATERIAL, "displacement_pixels", K_DOUBLE,
     AT(content.material.displacement_pixels), 0.5, 64, 0, NULL, "PX",
     "edge length to subdivide to"},
    {"displacement-triangles", 0, OPTIONS_MATERIAL, "displacement_triangles", K_INT,
     AT(content.material.displacement_triangles), 1000, 16000000, 1, NULL, "N",
     "most triangles subdivision may make"},
    {"lit", 0, OPTIONS_MATERIAL, "lit", K_CHOICE, AT(content.material.lit), 0, 0, 0, lit_names,
     "HOW", "diffuse + Blinn-Phong instead of the matcap: off, on, beside (both)"},
    {"lit-shininess", 0, OPTIONS_MATERIAL, "lit_shininess", K_DOUBLE,
     AT(content.material.shininess), 1, 256, 0, NULL, "N", "the lit mode's specular exponent"},
    {"unlit", 0, OPTIONS_MATERIAL, "unlit", K_CHOICE, AT(content.material.unlit), 0, 0, 0,
     unlit_names, "HOW", "KHR_materials_unlit parts: file (their colour alone), shade (matcap)"},
    {"camera", 0, OPTIONS_CAMERA, "enabled", K_CHOICE, AT(camera.use), 0, 0, 0, camera_names,
     "WHEN", "on: a live camera is the matcap whenever one is there; off: never"},
    {"camera-id", 0, OPTIONS_CAMERA, "id", K_STRING, AT(camera.id), 0, 0, 0, NULL, "ID",
     "the camera, by libcamera id or by index (0: the first)"},
    {"camera-size", 0, OPTIONS_CAMERA, "size", K_SIZE, AT(camera.width), 16, 4096, 1, NULL, "WxH",
     "the frame size asked of the camera"},
    {"camera-crop-x", 0, OPTIONS_CAMERA, "crop_x", K_DOUBLE, AT(camera.view.cx), 0, 1, 0, NULL, "X",
     "the ball's centre, 0 (left) to 1 (right) of the frame"},
    {"camera-crop-y", 0, OPTIONS_CAMERA, "crop_y", K_DOUBLE, AT(camera.view.cy), 0, 1, 0, NULL, "Y",
     "the ball's centre, 0 (top) to 1 (bottom) of the frame"},
    {"camera-crop-radius", 0, OPTIONS_CAMERA, "crop_radius", K_DOUBLE, AT(camera.view.radius), 0.01,
     1, 0, NULL, "R", "the ball's radius, in shares of the frame's shorter side"},
    {"camera-mirror", 0, OPTIONS_CAMERA, "mirror", K_FLAG, AT(camera.view.mirror), 0, 0, 0, NULL,
     NULL, "mirror the camera picture left to right"},
    {"camera-stall", 0, OPTIONS_CAMERA, "stall_timeout", K_DOUBLE, AT(camera.stall_s), 0.2, 600, 0,
     NULL, "S", "seconds without a frame before the camera counts as lost"},
    {"camera-import", 0, OPTIONS_CAMERA, "import", K_CHOICE, AT(camera.import), 0, 0, 0,
     import_names, "HOW",
     "auto: frames as EGLImages where the driver takes them; off: always upload"},
    {"schedule", 0, OPTIONS_POWER, "schedule", K_STRING, AT(power.schedule), 0, 0, 0, NULL, "WHEN",
     "when the screen is on, e.g. 'Mon-Fri 08:00-20:00, Sat 10:00-16:00' (default: always)"},
    {"blank-after", 0, OPTIONS_POWER, "blank_after", K_DOUBLE, AT(power.blank_after), 0, 10080, 0,
     NULL, "MIN", "the screen sleeps after this many minutes without input; 0: never"},
    {"cec", 0, OPTIONS_POWER, "cec", K_FLAG, AT(power.cec), 0, 0, 0, NULL, NULL,
     "also put an HDMI-CEC TV to standby and wake it"},
    {"cec-device", 0, OPTIONS_POWER, "cec_device", K_STRING, AT(power.cec_device), 0, 0, 0, NULL,
     "DEV", "the CEC adapter (default /dev/cec0)"},
    {"touch", 0, OPTIONS_TOUCH, "device", K_STRING, AT(touch.device), 0, 0, 0, NULL, "DEV",
     "auto (every touchscreen, also those plugged in later), off, or one /dev/input/eventN"},
    {"drag-speed", 0, OPTIONS_TOUCH, "drag_speed", K_DEGREES, AT(app.drag_speed), 10, 1440, 0, NULL,
     "DEG", "how far a one-finger drag across the whole screen turns the model"},
    {"touch-long-press", 0, OPTIONS_TOUCH, "long_press", K_CHOICE, AT(app.long_press), 0, 0, 0,
     app_action_names, "ACT", "what a long touch does (none: nothing)"},
    {"base-color", 0, OPTIONS_SCENE, "base_color", K_CHOICE, AT(content.material.base_color), 0, 0,
     0, base_color_names, "WHAT",
     "auto: the matcap times the model's base colour (glTF colour, texture, COLOR_0); off: not"},
    {"model-scene", 0, OPTIONS_SCENE, "model_scene", K_STRING, AT(content.model_scene), 0, 0, 0,
     NULL, "SCENE", "which of the model's glTF scenes: an index or a name (default: its own)"},
    {"variant", 0, OPTIONS_SCENE, "variant", K_STRING, AT(content.variant), 0, 0, 0, NULL, "NAME",
     "the glTF file's KHR_materials_variants variant shown first (default: its own materials)"},
    {"animation", 0, OPTIONS_SCENE, "animation", K_STRING, AT(content.animation), 0, 0, 0, NULL,
     "WHICH",
     "the glTF animation played, or posed for --time: auto (the first), off, all, an index or a "
     "name"},
    {"loop", 0, OPTIONS_SCENE, "loop", K_CHOICE, AT(content.anim_loop), 0, 0, 0, loop_names, "HOW",
     "how the animation goes on past its end: repeat, once (holds the last frame), pingpong"},
    {"speed", 0, OPTIONS_SCENE, "speed", K_DOUBLE, AT(content.anim_speed), 0.01, 100, 0, NULL, "X",
     "the animation's speed (1: as the file has it)"},
    {"animation-fps", 0, OPTIONS_SCENE, "animation_fps", K_DOUBLE, AT(content.anim_fps), 0, 240, 0,
     NULL, "FPS", "frames per second at most while the animation plays; 0: the display's rate"},
    {"animation-pause-after", 0, OPTIONS_SCENE, "animation_pause_after", K_DOUBLE,
     AT(content.anim_pause_after), 0, 31536000, 0, NULL, "S",
     "seconds without input before the animation pauses (no frames drawn); 0: never"},
    {"time", 0, OPTION_CLI, NULL, K_DOUBLE, AT(content.anim_time), 0, 1e9, 0, NULL, "SECONDS",
     "draw the model as its animation poses it this many seconds after it starts (with "
     "--output)"},
    {"config", 'C', OPTION_CLI, NULL, K_STRING, AT(config), 0, 0, 0, NULL, "FILE",
     "read settings from an INI file first (see config/kiosk.ini)"},
    {"output", 'o', OPTION_CLI, NULL, K_STRING, AT(output), 0, 0, 0, NULL, "FILE",
     "draw offscreen and write the last frame as PNG"},
    {"frames", 0, OPTION_CLI, NULL, K_INT, AT(frames), 1, 1e8, 1, NULL, "N",
     "frames to draw offscreen (default 1)"},
    {"stats", 0, OPTION_CLI, NULL, K_FLAG, AT(stats), 0, 0, 0, NULL, NULL,
     "print frame timings and peak memory"},
    {"shader-dir", 0, OPTION_CLI, NULL, K_STRING, AT(shader_dir), 0, 0, 0, NULL, "DIR",
     "read shaders from DIR instead of the built-in copy"},
    {"help", 'h', OPTION_CLI, NULL, K_FLAG, AT(help), 0, 0, 0, NULL, NULL, "this text"},
    {"version", 'V', OPTION_CLI, NULL, K_FLAG, AT(version), 0, 0, 0, NULL, NULL, "the version"},
    {"poster", 0, OPTIONS_DISPLAY, "poster", K_STRING, AT(poster), 0, 0, 0, NULL, "FILE",
     "a PNG/JPEG shown from the start until the model is ready (default: the background)"},
    {"include", 0, OPTIONS_KIOSK, "include", K_STRING, AT(include), 0, 0, 0, NULL, "FILE",
     "a second INI file read over this one and its .d/ files where it exists (a USB stick's, "
     "from --import)"},
    {"coarse-above", 0, OPTIONS_KIOSK, "coarse_above", K_INT, AT(content.coarse_above), 0, 1e9, 1,
     NULL, "N",
     "a live model of more than N triangles, not in the cache, is shown coarse first, then whole; "
     "0: never"},
    {"clock", 0, OPTIONS_KIOSK, "clock", K_CHOICE, AT(app.shared_clock), 0, 0, 0, clock_names,
     "CLOCK",
     "own, or shared: what moves by itself follows the wall clock, so kiosks whose clocks chrony "
     "keeps together move in step"},
    {"status", 0, OPTION_CLI, NULL, K_FLAG, AT(status), 0, 0, 0, NULL, NULL,
     "ask the running kiosk for its frame (PNG) and state (JSON), print the JSON, exit"},
    {"check-config", 0, OPTION_CLI, NULL, K_FLAG, AT(check_config), 0, 0, 0, NULL, NULL,
     "read the settings, load every file they name, say what is wrong, and exit (0 valid, 78 a "
     "bad setting, 66 a named file missing or broken)"},
    {"import", 0, OPTION_CLI, NULL, K_STRING, AT(import), 0, 0, 0, NULL, "DIR",
     "copy a USB stick's matcap-kiosk/ folder into the content folder, checked first; exit"},
    {"metrics", 0, OPTIONS_STATUS, "metrics", K_STRING, AT(metrics), 0, 0, 0, NULL, "FILE",
     "write the state every 5 s as a Prometheus text file (FILE.prom, for node_exporter's "
     "textfile collector)"},
    {"background", 0, OPTIONS_DISPLAY, "background", K_STRING, AT(content.background), 0, 0, 0,
     NULL, "WHAT",
     "behind the model: a colour #rrggbb, a vertical gradient '#top, #bottom', or a PNG/JPEG "
     "scaled to cover the screen (default: dark grey)"},
    {"antialias", 0, OPTIONS_DISPLAY, "antialias", K_CHOICE, AT(display.antialias), 0, 0, 0,
     antialias_names, "N",
     "smooth edges by multisampling: auto (4 samples on a GPU, off on a software rasteriser), "
     "off, 2, 4 or 8"},
    {"matcap-first", 0, OPTIONS_SCENE, "matcap_first", K_STRING, AT(content.matcap_first), 0, 0, 0,
     NULL, "NAME",
     "the matcap of the folder shown first, by file name; auto (default): a model with "
     "colours of its own on a neutral one (pearl, else the least tinted), another on gold "
     "(the shipped folder) or the folder's first by name"},
    {"zoom", 0, OPTION_CLI, NULL, K_DOUBLE, AT(content.zoom), 0.05, 20, 0, NULL, "Z",
     "draw at this scale of the sphere's framing instead of the one [scene] fit chose (logged "
     "at debug), so stills of other views keep one size"},
    {"stop", 0, OPTION_CLI, NULL, K_INT, AT(preview_stop), 1, 8, 1, NULL, "N",
     "with --output: draw what the kiosk shows at [frame] stops' Nth stop (1 the first), its "
     "view and its text, as a visitor's presses leave it"},
    {"at", 0, OPTION_CLI, NULL, K_DOUBLE, AT(preview_at), 0, 1e7, 0, NULL, "SECONDS",
     "with --output: draw what the attract tour shows this many seconds after it begins (the "
     "stops in turn, or the turn), caption and all"},
    {"fit", 0, OPTIONS_SCENE, "fit", K_DOUBLE, AT(content.fit), 0.1, 1, 0, NULL, "SHARE",
     "the share of the frame the model fills at its start view; it stays inside as it turns"},
    {"render-scale", 0, OPTIONS_DISPLAY, "render_scale", K_DOUBLE, AT(display.render_scale), 0.5, 1,
     0, auto_names, "S",
     "draw the model at this share of the panel's width and height, scaled up on the way out "
     "(the KMS plane where it can, else one GL pass); auto: 1 up to 1080p (1440p on a GPU), "
     "less on a larger panel (in software only where the plane scales)"},
    {"frame-up", 0, OPTIONS_FRAME, "up", K_CHOICE, AT(content.frame.up), 0, 0, 0, up_names, "AXIS",
     "the model's axis that points up: +y (glTF's), -y, +z, -z, +x or -x"},
    {"orientation", 0, OPTIONS_FRAME, "orientation", K_STRING, AT(content.frame.orientation), 0, 0,
     0, NULL, "'R P Y'",
     "turn the model by ROLL PITCH YAW degrees (after up, before the fit: the fit frames the "
     "turned model)"},
    {"start-yaw", 0, OPTIONS_FRAME, "yaw", K_DOUBLE, AT(content.frame.yaw), -360, 360, 0, NULL,
     "DEG", "the start view's turn about the vertical (default: [scene] yaw)"},
    {"start-pitch", 0, OPTIONS_FRAME, "pitch", K_DOUBLE, AT(content.frame.pitch), -90, 90, 0, NULL,
     "DEG", "the start view's tilt (default: [scene] pitch)"},
    {"start-zoom", 0, OPTIONS_FRAME, "zoom", K_DOUBLE, AT(content.frame.zoom), 0.05, 20, 0, NULL,
     "Z", "the start view's zoom, 1: the fit's"},
    {"yaw-min", 0, OPTIONS_FRAME, "yaw_min", K_DOUBLE, AT(content.frame.yaw_min), -3600, 3600, 0,
     NULL, "DEG", "no turn left of this yaw (with yaw_max: a turntable between them)"},
    {"yaw-max", 0, OPTIONS_FRAME, "yaw_max", K_DOUBLE, AT(content.frame.yaw_max), -3600, 3600, 0,
     NULL, "DEG", "no turn right of this yaw"},
    {"pitch-min", 0, OPTIONS_FRAME, "pitch_min", K_DOUBLE, AT(content.frame.pitch_min), -180, 180,
     0, NULL, "DEG", "no tilt below this pitch"},
    {"pitch-max", 0, OPTIONS_FRAME, "pitch_max", K_DOUBLE, AT(content.frame.pitch_max), -180, 180,
     0, NULL, "DEG", "no tilt above this pitch"},
    {"zoom-min", 0, OPTIONS_FRAME, "zoom_min", K_DOUBLE, AT(content.frame.zoom_min), 0.05, 20, 0,
     NULL, "Z", "the least zoom a pinch or a stop reaches (default 0.5)"},
    {"zoom-max", 0, OPTIONS_FRAME, "zoom_max", K_DOUBLE, AT(content.frame.zoom_max), 0.05, 20, 0,
     NULL, "Z", "the most zoom (default 4)"},
    {"attract-direction", 0, OPTIONS_FRAME, "attract_direction", K_CHOICE,
     AT(content.frame.attract_direction), 0, 0, 0, direction_names, "WAY",
     "attract mode turns right or left"},
    {"attract-sway", 0, OPTIONS_FRAME, "attract_sway", K_DOUBLE, AT(content.frame.attract_sway), 0,
     180, 0, NULL, "DEG",
     "attract mode swings this far each way of the start view instead of turning; 0: full turns"},
    {"stops", 0, OPTIONS_FRAME, "stops", K_STRING, AT(content.frame.stops), 0, 0, 0, NULL,
     "'Y P Z \"TEXT\" animation=CLIP variant=NAME; ...'",
     "guided stops: views (yaw, pitch in degrees, zoom) each with a line of text, a clip "
     "played and a material variant shown there, stepped by next-stop and prev-stop"},
    {"stop-seconds", 0, OPTIONS_FRAME, "stop_seconds", K_DOUBLE, AT(content.frame.stop_seconds), 0,
     3600, 0, NULL, "S", "attract mode plays the stops in turn, each this long; 0: it turns"},
    {"caption", 0, OPTIONS_CAPTION, "text", K_STRING, AT(content.caption.text), 0, 0, 0, NULL,
     "TEXT",
     "a caption over the model, UTF-8: wrapped between words to the frame's width (\\n breaks "
     "the line); a character the font lacks is drawn from an installed font that has it "
     "(--check-config names those none has); text[de] = gives it in a language; auto: the "
     "model's name (its glTF title or scene name, else its file's); default: none"},
    {"caption-font", 0, OPTIONS_CAPTION, "font", K_STRING, AT(content.caption.font), 0, 0, 0, NULL,
     "FILE", "a TrueType/OpenType font (default: DejaVu Sans, fonts-dejavu-core)"},
    {"caption-size", 0, OPTIONS_CAPTION, "size", K_DOUBLE, AT(content.caption.size), 6, 400, 0,
     NULL, "PX", "the text's size in pixels of the panel"},
    {"caption-color", 0, OPTIONS_CAPTION, "color", K_STRING, AT(content.caption.color), 0, 0, 0,
     NULL, "COLOR", "the text's colour, #rrggbb or #rrggbbaa (default: white)"},
    {"caption-box", 0, OPTIONS_CAPTION, "box", K_STRING, AT(content.caption.box), 0, 0, 0, NULL,
     "COLOR", "the box behind it, #rrggbbaa, aa its opacity (default: #00000099); none: no box"},
    {"caption-padding", 0, OPTIONS_CAPTION, "padding", K_INT, AT(content.caption.padding), 0, 400,
     1, NULL, "PX", "pixels inside the box, and between the box and the screen's edge"},
    {"caption-position", 0, OPTIONS_CAPTION, "position", K_CHOICE, AT(content.caption.position), 0,
     0, 0, position_names, "WHERE",
     "bottom-left, bottom-right, top-left, top-right, bottom or top"},
    {"caption-drift", 0, OPTIONS_CAPTION, "drift", K_CHOICE, AT(content.caption.drift), 0, 0, 0,
     drift_names, "WHEN",
     "on: the caption moves a few pixels over hours against burn-in; off: it stays"},
    {"logo", 0, OPTIONS_CAPTION, "logo", K_STRING, AT(content.caption.logo), 0, 0, 0, NULL, "FILE",
     "a PNG/JPEG shown at its own size in the caption's box, left of the text"},
    {"knob", 0, OPTIONS_KNOB, "device", K_STRING, AT(knob.device), 0, 0, 0, NULL, "DEV",
     "auto (every knob udev finds: REL_DIAL, REL_WHEEL or REL_X, no mouse), none, or one "
     "/dev/input/eventN"},
    {"knob-step", 0, OPTIONS_KNOB, "step", K_DEGREES, AT(knob.step), 1, 180, 0, NULL, "DEG",
     "how far a detent turns the model"},
    {"knob-turns", 0, OPTIONS_KNOB, "turns", K_CHOICE, AT(knob.turns), 0, 0, 0, knob_turns_names,
     "WHAT", "what a detent does: model (turns it) or stops (the next or previous stop)"},
    {"knob-press", 0, OPTIONS_KNOB, "press", K_CHOICE, AT(knob.press), 0, 0, 0, app_action_names,
     "ACT", "what a press of the knob's key (KEY_ENTER on the knob) does"},
    {"knob-long-press", 0, OPTIONS_KNOB, "long_press", K_CHOICE, AT(knob.long_press), 0, 0, 0,
     app_action_names, "ACT", "what a long press of the knob's key does (none: no long press)"},
    {"mqtt-broker", 0, OPTIONS_MQTT, "broker", K_STRING, AT(mqtt.broker), 0, 0, 0, NULL,
     "HOST[:PORT]",
     "remote control: the MQTT broker (port 1883, 8883 with tls); default: none, MQTT off"},
    {"mqtt-topic", 0, OPTIONS_MQTT, "topic", K_STRING, AT(mqtt.topic), 0, 0, 0, NULL, "TOPIC",
     "the kiosk's topic: commands on TOPIC/command, state on TOPIC/state (default: "
     "kiosk/HOSTNAME)"},
    {"mqtt-tls", 0, OPTIONS_MQTT, "tls", K_CHOICE, AT(mqtt.tls), 0, 0, 0, yes_no_names, "yes|no",
     "TLS to the broker, its certificate checked"},
    {"mqtt-ca-file", 0, OPTIONS_MQTT, "ca_file", K_STRING, AT(mqtt.ca_file), 0, 0, 0, NULL, "FILE",
     "the broker's CA certificate, PEM (default: the system's, /etc/ssl/certs)"},
    {"mqtt-home-assistant", 0, OPTIONS_MQTT, "home_assistant", K_CHOICE, AT(mqtt.home_assistant), 0,
     0, 0, yes_no_names, "yes|no",
     "announce the kiosk and its controls to Home Assistant (MQTT discovery)"},
    {"mqtt-sync", 0, OPTIONS_MQTT, "sync", K_CHOICE, AT(mqtt.sync), 0, 0, 0, sync_names, "ROLE",
     "kiosks showing one exhibit: the leader publishes the model, matcap and stop it shows "
     "with the wall-clock time, followers show the same from then; off, leader or follower"},
    {"mqtt-group", 0, OPTIONS_MQTT, "group", K_STRING, AT(mqtt.group), 0, 0, 0, NULL, "TOPIC",
     "the topic a leader and its followers share (default: kiosk/group)"},
    {"caption-languages", 0, OPTIONS_CAPTION, "languages", K_STRING, AT(content.caption.languages),
     0, 0, 0, NULL, "CODES",
     "the languages of the texts, in the order shown (e.g. en de fr): KEY[LANG] = gives a text "
     "in one (text[de] =, [frame] stops[de] = \"A\"; \"B\"), the plain KEY = is the first's "
     "and stands in for a text missing in another; next-language switches, attract mode shows "
     "each in turn, the first comes back after idle_seconds"},
    {"lang", 0, OPTION_CLI, NULL, K_STRING, AT(content.lang), 0, 0, 0, NULL, "CODE",
     "show the texts in this language of [caption] languages (with --output)"},
    {"hotspot", 0, OPTION_CLI, NULL, K_INT, AT(hotspot), 1, 8, 0, NULL, "N",
     "draw offscreen the view of the model's hotspot N (1: its first [hotspot.NAME]) with its "
     "text, as a stop at it shows it (with --output)"},
    {"as-output", 0, OPTION_CLI, NULL, K_STRING, AT(as_output), 0, 0, 0, NULL, "NAME",
     "with --output: draw the still as output NAME shows it ([output.NAME]: its view, "
     "rotation, caption and background)"},
    {"wall-columns", 0, OPTIONS_WALL, "columns", K_INT, AT(content.wall.columns), 1, WALL_MAX, 0,
     NULL, "N", "a wall of screens showing one picture: its screens across (1: no wall)"},
    {"wall-rows", 0, OPTIONS_WALL, "rows", K_INT, AT(content.wall.rows), 1, WALL_MAX, 0, NULL, "N",
     "the wall's screens down (1: no wall)"},
    {"wall-position", 0, OPTIONS_WALL, "position", K_PAIR, AT(content.wall.column), 1, WALL_MAX, 0,
     NULL, "COLUMN,ROW",
     "this screen's place in the wall, from 1,1 at the top left (2,1: the second across); "
     "outside the wall: the whole picture, said in the journal"},
    {"wall-bezel", 0, OPTIONS_WALL, "bezel", K_DOUBLE, AT(content.wall.bezel), 0, WALL_BEZEL_MAX, 0,
     NULL, "MM",
     "millimetres of dark frame between two screens' pictures, both frames together: "
     "the picture goes on behind it (needs screen_size)"},
    {"wall-screen-size", 0, OPTIONS_WALL, "screen_size", K_SIZE, AT(content.wall.screen_w), 1, 5000,
     1, NULL, "WxH",
     "millimetres of one screen's picture (its active area), to turn the bezel into pixels"},
};

const char *backend_name(enum backend_kind kind)
{
	return backend_names[kind];
}
