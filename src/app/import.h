/* --import DIR: a USB stick's matcap-kiosk/ folder into the content
 * folder ($STATE_DIRECTORY/content, else /var/lib/matcap-kiosk/content),
 * for the udev rule's unit (systemd/matcap-kiosk-import@.service). Only
 * models (.gltf, .glb, .bin), images (.png, .jpg, .jpeg), a matcaps/
 * folder of images and a kiosk.ini are copied; nothing from the stick is
 * run. The copy is staged beside the content folder, checked (the
 * settings parse, the model and matcaps load), synced to disk and only
 * then swapped in with one rename, so a stick with bad files, or a power
 * cut halfway, leaves the content that was working. The kiosk reads
 * content/kiosk.ini through [kiosk] include. */
#ifndef MK_IMPORT_H
#define MK_IMPORT_H

#include "app/settings.h"

/* o: the settings the kiosk runs with (the stick's go over them). Returns
 * 0, or a negative errno after saying why (-EINVAL: bad settings). */
int import_run(const struct options *o);

#endif
