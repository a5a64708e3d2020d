/* interp_fogbehind.c: fog of primitives that reach behind the eye
 * (docs/mapping.md "Fog behind the eye").
 *
 * GL fogs a vertex by its eye distance, |z_eye| for Mesa's
 * GL_FRAGMENT_DEPTH (GL 2.1 3.10), and interpolates that across the
 * primitive after clipping. A vertex behind the eye folds |z| back up, so
 * where the near plane cuts such an edge the interpolated coordinate is
 * larger than the true distance and GL's fog is denser there. POV-Ray fogs
 * each ray by its length: a whole note, since no scene fog reproduces it.
 */
#include "interp_internal.h"

void interp_fog_behind_check(interp *ip, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    if (!a->caps[INTERP_CAP_FOG] || !ip->scene || ip->prim_skip)
        return;
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    bool behind = false, ahead = false;
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, o[4];
        mat4_apply(mv, in, o);
        if (!(o[3] != 0))
            continue;
        double z = o[2] / o[3];
        behind |= z > 0;
        ahead |= z < 0;
    }
    if (behind && ahead)
        interp_note(ip, DIAG_NOTE_FOG_BEHIND);
}
