/* interp_fogbehind.c: the eye distance fog takes, and fog that GL
 * interpolates where the distance the writer fogs by does not follow it
 * (docs/mapping.md "Faces lit and fogged as GL does them", "Silent
 * differences, round 2").
 *
 * GL fogs a vertex by its eye distance c (GL 2.1 3.10; NV_fog_distance's
 * GL_FOG_DISTANCE_MODE_NV picks it: |z_eye| by default in Mesa, z_eye, or
 * the radial sqrt(x^2 + y^2 + z^2)) and interpolates c across the
 * primitive after clipping, perspective-correct: over one triangle the fog
 * coordinate is the affine function taking c_i at its corners. The writer
 * fogs each pixel by its own distance. For |z_eye| the two agree on a
 * triangle wholly in front of the eye (-z_eye is affine); a corner behind
 * the eye folds |z| back up, so GL's fog is denser there than the
 * distance says. z_eye is affine everywhere. The radial distance is not:
 * GL's interpolation lies above it inside a triangle, by more the larger
 * the triangle is against its distance. Such triangles get a mesh of their
 * own, fogged by the affine function (scene_look.fog_plane): exact. Lines
 * and unfilled polygons keep the distance (a note where they reach behind
 * the eye under |z_eye|).
 */
#include "interp_internal.h"
#include "talloc.h"

int interp_fog_distance_kind(const interp *ip)
{
    switch (ip->st.a.fog.distance) {
    case GL_EYE_PLANE: return SCENE_FOG_Z;
    case GL_EYE_RADIAL_NV: return SCENE_FOG_RADIAL;
    default: return SCENE_FOG_ABS_Z;
    }
}

double interp_fog_distance(const interp *ip, const double eye[3])
{
    switch (ip->st.a.fog.distance) {
    case GL_EYE_PLANE: return eye[2];
    case GL_EYE_RADIAL_NV: return sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
    default: return fabs(eye[2]);
    }
}

void interp_fog_behind_check(interp *ip, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    ip->fog_split = false;
    if (!a->caps[INTERP_CAP_FOG] || !ip->scene || ip->prim_skip || a->fog.distance == GL_EYE_PLANE)
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
        double w = o[3] != 0 ? o[3] : 1;
        for (int k = 0; k < 3; k++)
            ip->fogz[i][k] = o[3] != 0 ? o[k] / w : 0;
        ip->fogz[i][3] = interp_fog_distance(ip, ip->fogz[i]);
        behind |= ip->fogz[i][2] > 0;
        ahead |= ip->fogz[i][2] < 0;
    }
    bool filled = ip->prim_mode > GL_LINE_STRIP && a->polygon.mode[0] == GL_FILL &&
                  a->polygon.mode[1] == GL_FILL;
    if (a->fog.distance == GL_EYE_RADIAL_NV) {
        ip->fog_split = filled; /* each triangle tested (interp_fog_behind_mesh) */
        return;
    }
    if (!behind || !ahead)
        return;
    if (filled)
        ip->fog_split = true;
    else
        interp_note(ip, DIAG_NOTE_FOG_BEHIND);
}

/* How far GL's fog factor over the triangle of eye points e with
 * distances c may lie from the factor of the radial distance: at the
 * centroid and the edges' midpoints, times the factor's steepest slope. */
static double radial_error(const gl_attribs *a, double e[3][3], const double c[3])
{
    static const double wt[4][3] = {{1.0 / 3, 1.0 / 3, 1.0 / 3}, {0.5, 0.5, 0}, {0, 0.5, 0.5},
                                    {0.5, 0, 0.5}};
    double worst = 0;
    for (int q = 0; q < 4; q++) {
        double p[3] = {0, 0, 0}, gl = 0;
        for (int k = 0; k < 3; k++) {
            gl += wt[q][k] * c[k];
            for (int j = 0; j < 3; j++)
                p[j] += wt[q][k] * e[k][j];
        }
        double d = fabs(gl - sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
        worst = d > worst ? d : worst;
    }
    double slope;
    switch (a->fog.mode) {
    case GL_LINEAR: {
        double span = fabs((double)a->fog.end - a->fog.start);
        slope = span > 0 ? 1 / span : INFINITY;
        break;
    }
    case GL_EXP2: slope = 0.8578 * a->fog.density; break; /* sqrt(2) e^(-1/2) d */
    default: slope = a->fog.density; break;
    }
    return worst * slope;
}

scene_mesh *interp_fog_behind_mesh(interp *ip, const scene_look *look, const mat4 *to_eye,
                                   bool in_eye, uint32_t base, const uint32_t rel[3])
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    scene_look own = *look;
    double f[3], p[3][3], e[3][3];
    bool behind = false;
    for (int k = 0; k < 3; k++) {
        const double *z = ip->fogz[rel[k]];
        behind |= z[2] > 0;
        f[k] = z[3];
        for (int j = 0; j < 3; j++) {
            p[k][j] = s->verts[base + rel[k]].pos[j];
            e[k][j] = z[j];
        }
    }
    /* Half a level of the factor: below what the frame can show. */
    bool own_plane = a->fog.distance == GL_EYE_RADIAL_NV ? radial_error(a, e, f) > 0.5 / 255
                                                         : behind;
    if (own_plane) {
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
