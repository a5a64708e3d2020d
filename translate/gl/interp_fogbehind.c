/* interp_fogbehind.c: fog of primitives that reach behind the eye
 * (docs/mapping.md "Faces lit and fogged as GL does them").
 *
 * GL fogs a vertex by its eye distance, |z_eye| for Mesa's
 * GL_FRAGMENT_DEPTH (GL 2.1 3.10), and interpolates that across the
 * primitive after clipping, perspective-correct: over one triangle the
 * fog coordinate is the affine function taking |z_i| at its corners. For
 * a triangle wholly in front of the eye that is -z_eye, the writer's
 * eye-plane distance; a corner behind the eye folds |z| back up, so GL's
 * fog is denser there than the distance says. Such a triangle gets its
 * own mesh, fogged by that affine function (scene_look.fog_plane): exact.
 * Lines and unfilled polygons keep the distance, with a note.
 */
#include "interp_internal.h"
#include "talloc.h"

void interp_fog_behind_check(interp *ip, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    ip->fog_split = false;
    if (!a->caps[INTERP_CAP_FOG] || !ip->scene || ip->prim_skip)
        return;
    if (n > ip->cap_fogz && tr_grow((void **)&ip->fogz, &ip->cap_fogz, n, sizeof *ip->fogz) != 0) {
        ip->scene->failed = true;
        return;
    }
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    bool behind = false, ahead = false;
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, o[4];
        mat4_apply(mv, in, o);
        double z = o[3] != 0 ? o[2] / o[3] : 0;
        ip->fogz[i] = z;
        behind |= z > 0;
        ahead |= z < 0;
    }
    if (!behind || !ahead)
        return;
    if (ip->prim_mode > GL_LINE_STRIP && a->polygon.mode[0] == GL_FILL &&
        a->polygon.mode[1] == GL_FILL)
        ip->fog_split = true;
    else
        interp_note(ip, DIAG_NOTE_FOG_BEHIND);
}

scene_mesh *interp_fog_behind_mesh(interp *ip, const scene_look *look, const mat4 *to_eye,
                                   bool in_eye, uint32_t base, const uint32_t rel[3])
{
    scene *s = ip->scene;
    scene_look own = *look;
    double f[3], p[3][3];
    bool behind = false;
    for (int k = 0; k < 3; k++) {
        double z = ip->fogz[rel[k]];
        behind |= z > 0;
        f[k] = fabs(z);
        for (int j = 0; j < 3; j++)
            p[k][j] = s->verts[base + rel[k]].pos[j];
    }
    if (behind) {
        /* c.u = f1 - f0, c.v = f2 - f0, c.(u x v) = 0 */
        double u[3], w[3], nr[3], vn[3], nu[3];
        for (int j = 0; j < 3; j++)
            u[j] = p[1][j] - p[0][j], w[j] = p[2][j] - p[0][j];
        for (int j = 0; j < 3; j++)
            nr[j] = u[(j + 1) % 3] * w[(j + 2) % 3] - u[(j + 2) % 3] * w[(j + 1) % 3];
        for (int j = 0; j < 3; j++) {
            vn[j] = w[(j + 1) % 3] * nr[(j + 2) % 3] - w[(j + 2) % 3] * nr[(j + 1) % 3];
            nu[j] = nr[(j + 1) % 3] * u[(j + 2) % 3] - nr[(j + 2) % 3] * u[(j + 1) % 3];
        }
        double nn = nr[0] * nr[0] + nr[1] * nr[1] + nr[2] * nr[2];
        if (nn > 0 && isfinite(nn)) {
            double c[3], d = f[0];
            for (int j = 0; j < 3; j++) {
                c[j] = ((f[1] - f[0]) * vn[j] + (f[2] - f[0]) * nu[j]) / nn;
                d -= c[j] * p[0][j];
            }
            own.fog_own = 1;
            for (int j = 0; j < 3; j++)
                own.fog_plane[j] = (float)c[j];
            own.fog_plane[3] = (float)d;
        }
    }
    return scene_mesh_for(s, to_eye, in_eye, &own);
}
