// Morph targets on the GPU, compiled in only for a model whose targets
// play there (MORPH_TARGETS of them, at most 8; MORPH_NORMALS where they
// move normals): each target's deltas are attributes of their own, added
// with the pose's weights (u_morph_weights, four a vector) to the vertex's
// own position and normal, target by target, before the skin, as glTF
// orders them and as the CPU path adds them (scene/anim/anim_play.c). The C
// mirror of this sum: tests/unit/test_anim_play.c.

uniform vec4 u_morph_weights[2];

#ifdef MORPH_NORMALS
#define MORPH_ATTRIBUTES(p, n) attribute vec3 p; attribute vec3 n
#define MORPH_ADD(w, p, n) position += (w) * p; normal += (w) * n
#else
#define MORPH_ATTRIBUTES(p, n) attribute vec3 p
#define MORPH_ADD(w, p, n) position += (w) * p
#endif

MORPH_ATTRIBUTES(a_morph_p0, a_morph_n0);
#if MORPH_TARGETS > 1
MORPH_ATTRIBUTES(a_morph_p1, a_morph_n1);
#endif
#if MORPH_TARGETS > 2
MORPH_ATTRIBUTES(a_morph_p2, a_morph_n2);
#endif
#if MORPH_TARGETS > 3
MORPH_ATTRIBUTES(a_morph_p3, a_morph_n3);
#endif
#if MORPH_TARGETS > 4
MORPH_ATTRIBUTES(a_morph_p4, a_morph_n4);
#endif
#if MORPH_TARGETS > 5
MORPH_ATTRIBUTES(a_morph_p5, a_morph_n5);
#endif
#if MORPH_TARGETS > 6
MORPH_ATTRIBUTES(a_morph_p6, a_morph_n6);
#endif
#if MORPH_TARGETS > 7
MORPH_ATTRIBUTES(a_morph_p7, a_morph_n7);
#endif

void morph(inout vec3 position, inout vec3 normal)
{
	MORPH_ADD(u_morph_weights[0].x, a_morph_p0, a_morph_n0);
#if MORPH_TARGETS > 1
	MORPH_ADD(u_morph_weights[0].y, a_morph_p1, a_morph_n1);
#endif
#if MORPH_TARGETS > 2
	MORPH_ADD(u_morph_weights[0].z, a_morph_p2, a_morph_n2);
#endif
#if MORPH_TARGETS > 3
	MORPH_ADD(u_morph_weights[0].w, a_morph_p3, a_morph_n3);
#endif
#if MORPH_TARGETS > 4
	MORPH_ADD(u_morph_weights[1].x, a_morph_p4, a_morph_n4);
#endif
#if MORPH_TARGETS > 5
	MORPH_ADD(u_morph_weights[1].y, a_morph_p5, a_morph_n5);
#endif
#if MORPH_TARGETS > 6
	MORPH_ADD(u_morph_weights[1].z, a_morph_p6, a_morph_n6);
#endif
#if MORPH_TARGETS > 7
	MORPH_ADD(u_morph_weights[1].w, a_morph_p7, a_morph_n7);
#endif
}
