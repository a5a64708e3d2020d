/* interp_point.c: point parameters (glPointParameter, GL 1.4 3.3) and the
 * provoking vertex (glProvokingVertex, GL 3.2 2.19).
 *
 * A point's size follows its distance from the eye as GL derives it:
 * size * sqrt(1 / (a + b d + c d^2)), d = |z_eye|, clamped to [GL_POINT_SIZE_MIN,
 * GL_POINT_SIZE_MAX]; interp_assemble.c's add_point asks interp_point_size for
 * each point. GL fades points below GL_POINT_FADE_THRESHOLD_SIZE only when
 * multisampling, which a POV-Ray scene does not have: the threshold is
 * kept and noted, not drawn. The provoking vertex convention picks the
 * vertex whose colour a flat-shaded primitive takes (interp_assemble.c's pv).
 */
#include "interp_internal.h"

bool interp_point_params_set(const gl_attribs *a)
{
    return a->point.atten[0] != 1 || a->point.atten[1] != 0 || a->point.atten[2] != 0 ||
           a->point.size_min != 0 || a->point.size_max < a->point.size;
}

double interp_point_size(const gl_attribs *a, const double eye[3], double *fade)
{
    /* The spec's d is the distance to the eye; Mesa (the reference the
     * tests hold the translation to) takes |z_eye|, as most GLs do. */
    double d = fabs(eye[2]);
    double den = a->point.atten[0] + a->point.atten[1] * d + a->point.atten[2] * d * d;
    double size = a->point.size;
    if (den > 0 && isfinite(den))
        size *= sqrt(1 / den);
    else
        size = a->point.size_max; /* an infinite factor: the largest size */
    if (size < a->point.size_min)
        size = a->point.size_min;
    if (size > a->point.size_max)
        size = a->point.size_max;
    *fade = 1;
    return size > 0 ? size : 0;
}

void interp_pointparameter(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum pname = arg_enum(cmd, 0);
    const rgl_arg *pa = &cmd->arg[1];
    bool scalar = pa->kind == RGL_ARG_SCALAR;
    uint32_t n = scalar ? 1 : pa->count;
    double v[3] = {0, 0, 0};
    for (uint32_t k = 0; k < n && k < 3; k++)
        v[k] = scalar ? arg_num(pa) : pa->array[k];
    for (uint32_t k = 0; k < n && k < 3; k++)
        if (!isfinite(v[k])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "glPointParameter: a value is not finite");
            return;
        }
    struct gl_attribs *a = &ip->st.a;
    switch (pname) {
    case GL_POINT_SIZE_MIN: case GL_POINT_SIZE_MAX: case GL_POINT_FADE_THRESHOLD_SIZE:
        if (v[0] < 0) {
            interp_bad_value(ip, "negative point parameter");
            return;
        }
        if (pname == GL_POINT_SIZE_MIN)
            a->point.size_min = (float)fmin(v[0], 1024);
        else if (pname == GL_POINT_SIZE_MAX)
            a->point.size_max = (float)fmin(v[0], 1024);
        else
            a->point.fade_threshold = (float)fmin(v[0], 1024);
        break;
    case GL_POINT_DISTANCE_ATTENUATION:
        if (scalar || n < 3) {
            interp_bad_enum(ip, "point parameter of a scalar call", pname);
            return;
        }
        for (int k = 0; k < 3; k++)
            a->point.atten[k] = (float)v[k];
        break;
    case GL_POINT_SPRITE_COORD_ORIGIN: {
        GLenum e = interp_enum_of(v[0]);
        if (e != GL_LOWER_LEFT && e != GL_UPPER_LEFT) {
            interp_bad_enum(ip, "point sprite origin", e);
            return;
        }
        a->point.sprite_origin = e;
        break;
    }
    default:
        interp_bad_enum(ip, "point parameter", pname);
        return;
    }
}

void interp_provokingvertex(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0);
    if (interp_reject_in_begin(ip))
        return;
    if (m != GL_FIRST_VERTEX_CONVENTION && m != GL_LAST_VERTEX_CONVENTION) {
        interp_bad_enum(ip, "provoking vertex convention", m);
        return;
    }
    ip->st.a.lighting.provoking = m;
}
