/* The material maps the tests and goldens use, generated (no binary files
 * in the tree): a scaly relief as a packed detail map and as glTF normal,
 * occlusion and thickness textures, an egg-crate height map, a colour ramp
 * and a file that is not an image. */
#ifndef MK_MAPS_H
#define MK_MAPS_H

/* Writes detail.png, normal.png, occlusion.png, thickness.png, height.png,
 * ramp.png, base.png (BASE_SIDE square) and corrupt.png into dir. Returns
 * 0, or 1 after a message. */
#define BASE_SIDE 256
int maps_write(const char *dir);
/* A side x side PNG of one colour, written a row at a time: a few hundred
 * KB that decode to side^2 x 4 bytes (a zlib bomb). 0, or 1 after a
 * message. */
int maps_write_flat(const char *path, int side, const unsigned char rgba[4]);

#endif
