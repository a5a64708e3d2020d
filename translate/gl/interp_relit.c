/* interp_relit.c: GL's own per-vertex lighting for the faces POV-Ray
 * cannot light as GL does (docs/mapping.md "Faces lit as GL lights them").
 *
 * Back faces under one-sided lighting: GL lights them with the front
 * material and the normal as given, pointing away from the viewer, where
 * POV-Ray turns every normal toward the viewer. Back faces under two-sided
 * lighting whose colours vary per vertex: POV-Ray's interior_texture is
 * one texture for the whole mesh. Textured GL_MODULATE
 * surfaces lit past white: GL clamps the lit colour per vertex before the
 * texture multiplies it, POV-Ray does not. Untextured faces lit past white
 * too: GL clamps each vertex's colour and interpolates the clamped
 * colours, POV-Ray clamps each pixel of the interpolated light (an
 * emission from a colour array, issue 22). For those faces the
 * primitive's vertices are copied with GL's lit colour (as
 * --vertex-lighting does, interp_gouraud.c) into a second, unlit mesh;
 * the other faces keep POV-Ray's lighting. Untextured, that is done where
 * the colour without its highlights can pass white (a bound from the
 * material and the lights, so that most primitives never have GL's colour
 * made): a highlight that saturates keeps POV-Ray's per-pixel lighting, as
 * highlights do everywhere (see --vertex-lighting).
 */
#include "interp_internal.h"
#include "talloc.h"

#include <string.h>

bool interp_relit_wanted(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    return ip->scene && a->caps[INTERP_CAP_LIGHTING] && !interp_vertex_lit(ip) &&
           ip->prim_mode > GL_LINE_STRIP;
}

bool interp_relit_grow(interp *ip, size_t k)
{
    if (tr_grow((void **)&ip->relit_in, &ip->cap_relit_in, k + 1, sizeof *ip->relit_in) != 0) {
        ip->scene->failed = true;
        return false;
    }
    return true;
}

/* Made only when needed (a textured split reads the peak): lighting every
 * vertex was 14% of the instructions. Of GL's state only the material can
 * change between vertices (glMaterial), so the kept ones are made before. */
void interp_relit_flush(interp *ip)
{
    size_t n = ip->relit_pending, k0 = ip->relit_made;
    if (k0 >= n)
        return;
    if (n > ip->cap_relit &&
        tr_grow((void **)&ip->relit_col, &ip->cap_relit, n, sizeof *ip->relit_col) != 0) {
        ip->scene->failed = true;
        return;
    }
    interp_lit_prep lp;
    interp_relit_prepare(ip, &lp);
    for (size_t k = k0; k < n; k++) {
        double peak;
        interp_relit_colour(ip, &lp, &ip->relit_in[k], ip->relit_col[k], &peak);
        if (k == 0)
            ip->relit_over = false;
        /* GL clamps each channel to 1 (2.14.8); a little past it is rounding. */
        if (peak > 1 + 0.5 / 255)
            ip->relit_over = true;
    }
    ip->relit_made = n;
}

bool interp_relit_may_saturate(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    const gl_material *m = &a->lighting.material[0];
    GLenum cmm = a->lighting.color_material_mode;
    bool cm = a->caps[INTERP_CAP_COLOR_MATERIAL], any = ip->vmat.changed;
    bool cm_a = any || (cm && (cmm == GL_AMBIENT || cmm == GL_AMBIENT_AND_DIFFUSE));
    bool cm_d = any || (cm && (cmm == GL_DIFFUSE || cmm == GL_AMBIENT_AND_DIFFUSE));
    bool cm_e = any || (cm && cmm == GL_EMISSION);
    for (int k = 0; k < 3; k++) {
        double ka = cm_a ? 1 : m->ambient[k], kd = cm_d ? 1 : m->diffuse[k];
        double ke = cm_e ? 1 : m->emission[k];
        double sum = ke + ka * a->lighting.model_ambient[k];
        for (int l = 0; l < INTERP_MAX_LIGHTS; l++) {
            if (!a->caps[INTERP_CAP_LIGHT0 + l])
                continue;
            const gl_light *li = &a->lighting.light[l];
            const float *at = li->attenuation;
            /* GL 2.1 2.14.1: the attenuation is at most 1 / kc when no
             * factor is negative; unbounded otherwise. */
            double att = li->position[3] == 0 ? 1
                         : at[0] > 0 && at[1] >= 0 && at[2] >= 0 ? 1 / (double)at[0]
                                                                 : INFINITY;
            sum += att * (ka * li->ambient[k] + kd * li->diffuse[k]);
        }
        if (!(sum <= 1 + 0.5 / 255))
            return true;
    }
    return false;
}

int interp_relit_split(interp *ip, const scene_look *look)
{
    if (!look->lit || !interp_relit_wanted(ip))
        return 0;
    const gl_attribs *a = &ip->st.a;
    if (a->lighting.two_side) {
        /* GL lights a back face (by its winding) with the back material
         * and the normal turned; POV-Ray's interior_texture goes by the
         * side the interpolated normal faces and is one texture for the
         * whole mesh. So a back face whose normals face the viewer came
         * out lit as a front face (bright where GL's is dark), and colours
         * that vary per vertex came out in one. Untextured back faces take
         * GL's lit colours; textured ones keep the interior texture. */
        return look->texture < 0 ? INTERP_RELIT_BACK : 0;
    }
    /* GL_SEPARATE_SPECULAR_COLOR adds the highlight after the texture: an
     * unlit copy cannot carry it (interp_lit_color sums it in). */
    const float *ks = a->lighting.material[0].specular;
    if (look->texture >= 0 && a->lighting.color_control != GL_SINGLE_COLOR &&
        (ks[0] > 0 || ks[1] > 0 || ks[2] > 0)) {
        if (ip->relit_over)
            interp_note(ip, DIAG_NOTE_RELIT_SPECULAR);
        return INTERP_RELIT_PROBE; /* back faces are noted, not moved */
    }
    if (ip->relit_over && look->texture >= 0) {
        const scene_texture *t = &ip->scene->textures[look->texture];
        if (t->env_mode == SCENE_ENV_MODULATE && !t->colour_is_texel)
            return INTERP_RELIT_ALL;
    }
    if (ip->relit_over && look->texture < 0)
        return INTERP_RELIT_ALL;
    return INTERP_RELIT_BACK;
}

bool interp_relit_need_clear(interp *ip, uint32_t n)
{
    if (n > ip->cap_relit_need &&
        tr_grow((void **)&ip->relit_need, &ip->cap_relit_need, n, sizeof *ip->relit_need) != 0) {
        ip->scene->failed = true;
        return false;
    }
    memset(ip->relit_need, 0, n);
    ip->nrelit_tris = 0;
    return true;
}

bool interp_relit_vertices(interp *ip, uint32_t n)
{
    scene *s = ip->scene;
    if (n > ip->relit_pending || n > ip->cap_relit_need || s->nverts != ip->prim_first + n)
        return false;
    if (n > ip->cap_relit_copy &&
        tr_grow((void **)&ip->relit_copy, &ip->cap_relit_copy, n, sizeof *ip->relit_copy) != 0) {
        s->failed = true;
        return false;
    }
    /* Only the moved faces' corners are copied: the others would be in no
     * face (half the pool's vertices, on a closed surface). */
    const uint8_t *need = ip->relit_need;
    uint32_t m = 0;
    for (uint32_t i = 0; i < n; i++)
        m += need[i];
    /* interp_budget_vertex m times: at once when none of them can fail
     * (the pool's size does not change in between). */
    if (!ip->cut && ip->assembled + m <= INTERP_LIMIT(ip, ASSEMBLED) &&
        s->nverts < INTERP_LIMIT(ip, VERTICES))
        ip->assembled += m;
    else
        for (uint32_t i = 0; i < m; i++)
            if (!interp_budget_vertex(ip))
                return false;
    scene_vertex *v = scene_reserve_vertices(s, m);
    if (!v)
        return false;
    const scene_vertex *src = s->verts + ip->prim_first;
    interp_lit_prep lp;
    interp_relit_prepare(ip, &lp);
    uint32_t first = (uint32_t)s->nverts, j = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!need[i])
            continue;
        v[j] = src[i];
        if (i < ip->relit_made)
            memcpy(v[j].color, ip->relit_col[i], sizeof v[j].color);
        else
            interp_relit_colour(ip, &lp, &ip->relit_in[i], v[j].color, NULL);
        ip->relit_copy[i] = first + j++;
    }
    scene_commit_vertices(s, m);
    return true;
}

void interp_relit_done(interp *ip)
{
    ip->relit_over = false;
    ip->prim_relit = false;
    ip->relit_pending = ip->relit_made = 0;
    ip->nrelit_tris = 0;
}
