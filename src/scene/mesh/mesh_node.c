/* A model's named nodes (struct mesh_node): the rule a name kept must
 * follow, checked by the loader and again by the cache's reader, since
 * the name reaches the journal and a curator's error line. */
#include "scene/mesh/mesh.h"

#include <string.h>

/* The bytes of the UTF-8 sequence at s (1 to 4), or 0 when it is not
 * one: an overlong form, a surrogate, past U+10FFFF, a control. */
static int sequence(const unsigned char *s)
{
	unsigned c = s[0], cp;
	int n = c < 0x80	     ? 1
		: (c & 0xe0) == 0xc0 ? 2
		: (c & 0xf0) == 0xe0 ? 3
		: (c & 0xf8) == 0xf0 ? 4
				     : 0;

	if (n == 1)
		return c >= 0x20 && c != 0x7f;
	if (!n)
		return 0;
	cp = c & (0x7fu >> n);
	for (int k = 1; k < n; k++) {
		if ((s[k] & 0xc0) != 0x80)
			return 0;
		cp = cp << 6 | (s[k] & 0x3fu);
	}
	if ((n == 2 && cp < 0x80) || (n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) ||
	    (cp >= 0xd800 && cp <= 0xdfff) || cp > 0x10ffff || (cp >= 0x80 && cp < 0xa0))
		return 0;
	return n;
}

bool mesh_node_name_ok(const char *s)
{
	size_t len = s ? strnlen(s, MESH_NODE_NAME) : 0;

	if (!len || len >= MESH_NODE_NAME)
		return false;
	for (size_t i = 0; i < len;) {
		int n = sequence((const unsigned char *)s + i);

		if (!n)
			return false;
		i += (size_t)n;
	}
	return true;
}

const struct mesh_node *mesh_node_find(const struct mesh *m, const char *name)
{
	for (uint32_t i = 0; i < m->node_count && i < MESH_NODES; i++)
		if (!strcmp(m->nodes[i].name, name))
			return &m->nodes[i];
	return NULL;
}
