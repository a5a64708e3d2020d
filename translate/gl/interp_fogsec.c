/* interp_fogsec.c: fog coordinates and the secondary colour (GL 1.4;
 * GL 2.1 3.9 colour sum, 3.10 fog).
 *
 * GL adds the secondary colour after texturing (GL_COLOR_SUM, unlit) and
 * then fogs by f of the fragment's fog coordinate: its eye distance, or
 * with GL_FOG_COORD_SRC = GL_FOG_COORD the interpolated glFogCoord. Where
 * the vertex colour is GL's final colour (an untextured unlit draw, or lit
 * lines and points, which the interpreter lights itself), both go into the
 * vertex colour here, and POV-Ray interpolates it across the face as GL
 * interpolates the fog coordinate (Gouraud); such a draw then carries no
 * fog layer (interp_current_look). Lit or textured surfaces, whose colour
 * POV-Ray computes, keep the eye-distance fog layer, with a note. Lines
 * and points, built in eye space with GL's final colours, take the fog of
 * their eye distance at their ends (interp_fogsec_eye).
 */
#include "interp_internal.h"

#include <math.h>

/* GL 2.1 (3.16), with c the fog coordinate as given (Mesa takes no
 * absolute value of a glFogCoord). */
static double fog_factor(const gl_attribs *a, double c)
{
    double f;
    switch (a->fog.mode) {
    case GL_LINEAR: {
        double span = (double)a->fog.end - a->fog.start;
        f = span != 0 ? (a->fog.end - c) / span : c - a->fog.end; /* Mesa's, at start = end */
        break;
    }
    case GL_EXP2: {
        double dc = a->fog.density * c;
        f = exp(-dc * dc);
        break;
    }
    default:
        f = exp(-a->fog.density * c);
        break;
    }
    if (!(f > 0))
        return 0; /* also NaN */
    return f < 1 ? f : 1;
}

void interp_fogsec_begin(interp *ip, GLenum mode)
{
    const gl_attribs *a = &ip->st.a;
    const uint8_t *c = a->caps;
    bool lit_surface = c[INTERP_CAP_LIGHTING] && mode > GL_LINE_STRIP;
    bool final_colour = !lit_surface && ip->draw_unit[0] < 0 && ip->draw_unit[1] < 0;
    bool sum = c[INTERP_CAP_COLOR_SUM] && !c[INTERP_CAP_LIGHTING];
    bool coord = c[INTERP_CAP_FOG] && a->fog.coord_src == GL_FOG_COORD;
    ip->prim_color_sum = sum && final_colour;
    ip->prim_fog_vertex = coord && final_colour;
    ip->prim_coord_same = true;
    ip->prim_coord0 = a->current.fog_coord;
    if (sum && !final_colour)
        interp_note(ip, DIAG_NOTE_COLOR_SUM);
    if (coord && final_colour && (a->fog.mode != GL_LINEAR || a->lighting.shade_model == GL_FLAT))
        interp_note(ip, DIAG_NOTE_FOG_COORD_VERTEX);
}

void interp_fogsec_look(interp *ip, scene_look *look)
{
    const gl_attribs *a = &ip->st.a;
    if (!look->fog || a->fog.coord_src != GL_FOG_COORD)
        return;
    /* Lit or textured: POV-Ray computes the colour. One coordinate for
     * the whole draw is one factor: a fog layer of constant transmit. */
    if (ip->prim_coord_same) {
        look->fog_fixed = 1;
        look->fog_f = (float)fog_factor(a, ip->prim_coord0);
    } else {
        interp_note(ip, DIAG_NOTE_FOG_COORD);
    }
}

void interp_fogsec_track(interp *ip)
{
    if (ip->st.a.current.fog_coord != ip->prim_coord0)
        ip->prim_coord_same = false;
}

void interp_fogsec_eye(interp *ip, const double eye[3], float color[4])
{
    const gl_attribs *a = &ip->st.a;
    if (!a->caps[INTERP_CAP_FOG] || a->fog.coord_src != GL_FRAGMENT_DEPTH)
        return; /* unfogged, or fogged by the coordinate already */
    double c = interp_fog_distance(ip, eye), f = fog_factor(a, c);
    if (a->fog.mode != GL_LINEAR || ip->prim_blend_mapped ||
        c < fmin(a->fog.start, a->fog.end) || c > fmax(a->fog.start, a->fog.end))
        interp_note(ip, DIAG_NOTE_FOG_LINES);
    for (int k = 0; k < 3; k++)
        color[k] = (float)(f * color[k] + (1 - f) * a->fog.color[k]);
}

void interp_fogsec_vertex(interp *ip, float color[4])
{
    const gl_attribs *a = &ip->st.a;
    /* GL clamps the sum per fragment, after interpolating both colours;
     * POV-Ray clamps only the pixel, so the sum stays unclamped, unless
     * fog follows (GL fogs the clamped sum). */
    if (ip->prim_color_sum)
        for (int k = 0; k < 3; k++) {
            float v = color[k] + a->current.secondary[k];
            color[k] = v < 1 || !ip->prim_fog_vertex ? v : 1;
        }
    if (ip->prim_fog_vertex) {
        double c = a->current.fog_coord, f = fog_factor(a, c);
        /* A factor clamped at a vertex is not GL's clamp per fragment. */
        if (a->fog.mode == GL_LINEAR && (c < fmin(a->fog.start, a->fog.end) ||
                                         c > fmax(a->fog.start, a->fog.end)))
            interp_note(ip, DIAG_NOTE_FOG_COORD_VERTEX);
        for (int k = 0; k < 3; k++)
            color[k] = (float)(f * color[k] + (1 - f) * a->fog.color[k]);
    }
}
