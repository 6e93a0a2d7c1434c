/* --import DIR: a USB stick's matcap-kiosk/ folder into the content
 * folder ($STATE_DIRECTORY/content, else /var/lib/matcap-kiosk/content),
 * for the udev rule's unit (systemd/matcap-kiosk-import@.service). Only
 * plain files with printable names are copied, never through a link:
 * models (.gltf, .glb, .bin) and images (.png, .jpg, .jpeg) beside them,
 * a matcaps/ folder of images, and a kiosk.ini that may set [scene],
 * [material] and [kiosk] attract_*, turn_* and idle_seconds (no absolute
 * path, no ".."); links, pipes, sockets and device nodes are passed over
 * (ops/import_copy.h), and nothing from the stick is run. 2 GiB at most,
 * and no more than 90 % of the free space, sized before a byte is
 * copied. The copy is staged beside the content folder, checked (the
 * settings parse, every model they name and the matcaps load), synced to
 * disk and only then swapped in with one rename, one import at a time, so
 * a stick with bad files, two sticks at once or a power cut halfway leave
 * content that works; what a cut left is removed by the next import and
 * the kiosk's start. The kiosk reads content/kiosk.ini through [kiosk]
 * include. */
#ifndef MK_IMPORT_H
#define MK_IMPORT_H

#include "config/settings.h"

/* o: the settings the kiosk runs with (the stick's go over them). Returns
 * 0 (also when DIR is not there: a stick of other files), or a negative
 * errno after saying why (-EINVAL: bad settings). */
int import_run(const struct options *o);
/* The staging folder an import cut short left (the process stopped, the
 * power gone) removed, with a line; nothing while an import runs. For
 * the kiosk's start, so that no half copy stays on the card. */
void import_clean_stale(void);

#endif
