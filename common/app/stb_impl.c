/* stb_image and stb_image_write compiled in, where the system ships them as
 * headers only (Fedora, Arch, MSYS2, a folder given with STB_CFLAGS). Debian
 * and Ubuntu ship them compiled (libstb): the Makefile then links -lstb and
 * leaves this file out. */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
