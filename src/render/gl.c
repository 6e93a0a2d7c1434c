#include "render/gl.h"
#include "util/log.h"

#include <errno.h>
#include <string.h>

int gl_load(struct gl *gl, gl_get_proc_fn get_proc, void *ctx)
{
	void *p;

	memset(gl, 0, sizeof(*gl));
#define GL_LOAD(type, name)                                                                        \
	p = get_proc(ctx, "gl" #name);                                                             \
	if (!p) {                                                                                  \
		log_err("GL driver lacks gl" #name);                                               \
		return -ENOSYS;                                                                    \
	}                                                                                          \
	memcpy(&gl->name, &p, sizeof(p));
	GL_FUNCS(GL_LOAD)
#undef GL_LOAD
	return 0;
}
