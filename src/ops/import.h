/* --import DIR: a USB stick's matcap-kiosk/ folder into the content
 * folder ($STATE_DIRECTORY/content, else /var/lib/matcap-kiosk/content),
 * for the udev rule's unit (systemd/matcap-kiosk-import@.service). Only
 * plain files are copied, never through a link: models (.gltf, .glb,
 * .bin) and images (.png, .jpg, .jpeg) beside them, a matcaps/ folder of
 * images, and a kiosk.ini that may set [scene], [material] and [kiosk]
 * attract_*, turn_* and idle_seconds (no absolute path, no ".."); nothing
 * from the stick is run. 2 GiB at most, and no more than 90 % of the free
 * space. The copy is staged beside the content folder, checked (the
 * settings parse, the model and matcaps load), synced to disk and only
 * then swapped in with one rename, one import at a time, so a stick with
 * bad files, two sticks at once or a power cut halfway leave content that
 * works. The kiosk reads content/kiosk.ini through [kiosk] include. */
#ifndef MK_IMPORT_H
#define MK_IMPORT_H

#include "config/settings.h"

/* o: the settings the kiosk runs with (the stick's go over them). Returns
 * 0 (also when DIR is not there: a stick of other files), or a negative
 * errno after saying why (-EINVAL: bad settings). */
int import_run(const struct options *o);

#endif
