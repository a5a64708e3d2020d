/* interp_alphatest.c: the alpha test (GL 1.x 4.1.4, glAlphaFunc with
 * GL_ALPHA_TEST) of filled polygons.
 *
 * A fragment whose alpha fails the test is discarded. Two cases:
 *
 * - The texture's alpha counts (a base format with alpha under MODULATE
 *   or REPLACE): the test is per texel. The interpreter puts the function,
 *   the reference and the current vertex alpha into the scene texture
 *   (interp_texdraw.c) and the writer makes the failing texels fully
 *   transparent in the image (povwrite_texture.c): exact with GL_NEAREST,
 *   a soft edge one texel wide with GL_LINEAR (noted).
 * - Otherwise the fragment's alpha is the vertex alpha, interpolated over
 *   the face: a face whose every vertex fails is dropped here (the
 *   comparisons are monotone in alpha, so every point between fails
 *   too; GL_EQUAL and GL_NOTEQUAL hold the same at the corners); a face
 *   with corners on both sides of the reference is kept whole, with a note.
 */
#include "interp_internal.h"

bool interp_alpha_testing(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return a->caps[INTERP_CAP_ALPHA_TEST] && a->color_buffer.alpha_func != GL_ALWAYS;
}

static bool testing(const interp *ip) { return interp_alpha_testing(ip); }

uint8_t interp_alpha_vertex(interp *ip, size_t k, float a)
{
    if (!testing(ip))
        return 0;
    if (k == 0) {
        ip->prim_alpha = a;
        ip->prim_alpha_varies = false;
    } else if (a != ip->prim_alpha) {
        ip->prim_alpha_varies = true;
    }
    const gl_attribs *g = &ip->st.a;
    return scene_alpha_pass(interp_scene_cmp(g->color_buffer.alpha_func), a,
                            g->color_buffer.alpha_ref)
               ? 0
               : INTERP_ALPHA_FAIL;
}

bool interp_alpha_face(interp *ip, const uint32_t *idx, int n, int32_t texture)
{
    if (!testing(ip))
        return true;
    const scene_texture *t = texture >= 0 && ip->scene && (size_t)texture < ip->scene->ntextures
                                 ? &ip->scene->textures[texture]
                                 : NULL;
    int fail = 0;
    for (int k = 0; k < n; k++)
        fail += (ip->edge[idx[k]] & INTERP_ALPHA_FAIL) != 0;
    if (t && t->alpha_func) {
        /* Per texel, with one vertex alpha for the draw (the writer's). */
        if (t->alpha_uses_af && (ip->prim_alpha_varies || ip->prim_alpha != t->alpha_af))
            interp_note(ip, DIAG_NOTE_ALPHA_TEST);
        return true;
    }
    if (fail == n)
        return false;
    if (fail > 0)
        interp_note(ip, DIAG_NOTE_ALPHA_TEST);
    return true;
}
