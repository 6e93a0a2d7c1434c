/* libFuzzer: the PNG/JPEG/WebP decoder (libpng, libjpeg-turbo, libwebp and our checks
 * around them) on any bytes, as a matcap file would hand them over. An
 * image that decodes must be what the renderer uploads blindly: a size
 * within IMAGE_MAX_SIDE and every RGBA byte readable. */
#include "util/image.h"
#include "util/log.h"

#include <stdint.h>
#include <stdlib.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	log_set_level((enum log_level)0);
	return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct image img;
	unsigned sum = 0;

	if (image_decode("fuzz.png", data, size, &img) == 0) {
		if (img.width < 1 || img.height < 1 || img.width > IMAGE_MAX_SIDE ||
		    img.height > IMAGE_MAX_SIDE || !img.rgba)
			abort();
		/* First and last byte of each row: ASan checks the extent. */
		for (int y = 0; y < img.height; y++)
			sum += img.rgba[(size_t)y * (size_t)img.width * 4] +
			       img.rgba[((size_t)y + 1) * (size_t)img.width * 4 - 1];
		image_release(&img);
	}
	return (int)(sum & 0);
}
