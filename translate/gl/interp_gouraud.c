/* interp_gouraud.c: OpenGL's per-vertex lighting on request
 * (raygl2pov --vertex-lighting; docs/mapping.md "Lights per object,
 * shadows, Gouraud").
 *
 * GL lights each vertex and interpolates the colours (Gouraud); POV-Ray
 * lights each pixel. On finely tessellated surfaces the two agree; on
 * large faces and coarse meshes under point lights, spots or a local
 * viewer they do not (the per-pixel picture is the truer one). With
 * vertex lighting on, a lit filled primitive takes GL's lit colour at each
 * vertex (interp_lit_color, as lit lines and points always do) and is
 * drawn unlit: exactly GL's shading, but emissive, so without shadows or
 * ray-traced highlights. Two-sided lighting, which picks the colour by the
 * face's side, keeps POV-Ray's lighting.
 */
#include "interp_internal.h"

#include <math.h>

void interp_set_vertex_lighting(interp *ip, bool on) { ip->vertex_lighting = on; }

bool interp_vertex_lit(const interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    if (ip->prim_relit) /* the GL-lit faces of interp_relit.c */
        return true;
    return ip->vertex_lighting && a->caps[INTERP_CAP_LIGHTING] && !a->lighting.two_side;
}

/* Longest edge over distance to a light or the eye past which a face is
 * noted: the direction turns by about that many radians (a) across the
 * face. GL interpolates N.L linearly from the corners where POV-Ray
 * evaluates it at each pixel: off by about a^2/8 of the light in the
 * middle, 8/255 at a = 0.5 (lit_two_sided's tube, a = 0.25, agrees within
 * 4/255 on 99.999% of its pixels). */
#define GOURAUD_NOTE_LIGHT 0.5
#define GOURAUD_NOTE_EYE 0.5

void interp_gouraud_check(interp *ip, size_t first_tri)
{
    const gl_attribs *a = &ip->st.a;
    const scene *s = ip->scene;
    if (!s || ip->vertex_lighting || !a->caps[INTERP_CAP_LIGHTING] || first_tri >= s->ntris)
        return;
    /* The points whose direction varies over a face: positional lights,
     * and the eye with a local viewer and a highlight. Directional lights
     * with GL's infinite viewer light a flat face evenly either way. */
    double q[INTERP_MAX_LIGHTS + 1][3];
    int nq = 0;
    for (int i = 0; i < INTERP_MAX_LIGHTS; i++) {
        const gl_light *l = &a->lighting.light[i];
        if (!a->caps[INTERP_CAP_LIGHT0 + i] || l->position[3] == 0)
            continue;
        for (int k = 0; k < 3; k++)
            q[nq][k] = l->position[k] / l->position[3];
        nq++;
    }
    int nlights = nq;
    const float *ks = a->lighting.material[0].specular;
    if (a->lighting.local_viewer && (ks[0] > 0 || ks[1] > 0 || ks[2] > 0)) {
        q[nq][0] = q[nq][1] = q[nq][2] = 0;
        nq++;
    }
    if (nq == 0)
        return;
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    for (size_t t = first_tri; t < s->ntris; t++) {
        double p[3][3];
        for (int c = 0; c < 3; c++) {
            const float *v = s->verts[s->tris[t].v[c]].pos;
            double in[4] = {v[0], v[1], v[2], 1}, o[4];
            if (ip->prim_in_eye)
                o[0] = v[0], o[1] = v[1], o[2] = v[2], o[3] = 1;
            else
                mat4_apply(mv, in, o);
            for (int k = 0; k < 3; k++)
                p[c][k] = o[3] != 0 ? o[k] / o[3] : o[k];
        }
        double edge = 0, cen[3];
        for (int c = 0; c < 3; c++) {
            double e = 0;
            for (int k = 0; k < 3; k++)
                e += (p[c][k] - p[(c + 1) % 3][k]) * (p[c][k] - p[(c + 1) % 3][k]);
            edge = e > edge ? e : edge;
        }
        edge = sqrt(edge);
        for (int k = 0; k < 3; k++)
            cen[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
        for (int j = 0; j < nq; j++) {
            double d = sqrt((cen[0] - q[j][0]) * (cen[0] - q[j][0]) +
                            (cen[1] - q[j][1]) * (cen[1] - q[j][1]) +
                            (cen[2] - q[j][2]) * (cen[2] - q[j][2]));
            double ratio = j == nlights ? GOURAUD_NOTE_EYE : GOURAUD_NOTE_LIGHT;
            if (isfinite(edge) && edge > ratio * d) {
                interp_note(ip, DIAG_NOTE_GOURAUD);
                return;
            }
        }
    }
}
