/* A DSI panel's backlight (the official Raspberry Pi touch displays):
 * sleeping turns it off through sysfs, waking turns it on again at the
 * brightness it had. KMS alone stops the picture, but on these panels
 * only the backlight stops the glow. */
#ifndef MK_BACKLIGHT_H
#define MK_BACKLIGHT_H

#include <stdbool.h>

struct backlight;

/* The first device under class_dir (/sys/class/backlight; tests pass a
 * folder of their own). NULL when there is none (an HDMI screen): not an
 * error, said once at info level. */
struct backlight *backlight_new(const char *class_dir);
void backlight_free(struct backlight *b);
/* Returns 0 or a negative errno (logged: the service may lack the
 * permission, which the udev rule gives to the video group). */
int backlight_power(struct backlight *b, bool on);

#endif
