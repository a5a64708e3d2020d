/* interp_scissor.c: the scissor test (GL 1.x 4.1.2): glScissor, and
 * scissored clears.
 *
 * The box is an attribute (GL_SCISSOR_BIT); until the first glScissor it
 * is the whole window, which a trace does not hold, so an unset box
 * scissors nothing, and neither does a box that holds the whole viewport
 * (the picture is the viewport).
 *
 * A scissored glClear of the colour buffer paints only the box. The scene
 * keeps it as a rectangle of the clear colour at the box, unlit, just in
 * front of the far plane, so that all the frame draws later hides it as
 * GL's later draws cover the cleared pixels. The rectangles are placed at
 * the frame's end, through the frame's camera (which the first draw may
 * fix after the clear). What was drawn before a scissored clear inside its
 * box stays (GL erases it): a note says so.
 *
 * Scissored triangles and solids carry the box (in the camera's image) in
 * their look; the writer clips them to it exactly (clipped_by planes
 * through the camera's rays along the box's edges). Lines and points are
 * drawn whole, with a note.
 */
#include "interp_internal.h"

#include <string.h>

void interp_scissor(interp *ip, const rgl_cmd *cmd)
{
    int64_t w = rgl_arg_i(&cmd->arg[2], 0), h = rgl_arg_i(&cmd->arg[3], 0);
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "negative scissor size");
        return;
    }
    int32_t *b = ip->st.a.scissor.box;
    b[0] = (int32_t)rgl_arg_i(&cmd->arg[0], 0);
    b[1] = (int32_t)rgl_arg_i(&cmd->arg[1], 0);
    b[2] = (int32_t)w;
    b[3] = (int32_t)h;
    ip->st.a.scissor.set = true;
}

bool interp_scissor_cuts(const interp *ip, const int32_t vp[4])
{
    const gl_attribs *a = &ip->st.a;
    if (!a->caps[INTERP_CAP_SCISSOR_TEST] || !a->scissor.set)
        return false;
    const int32_t *b = a->scissor.box;
    return !((int64_t)b[0] <= vp[0] && (int64_t)b[1] <= vp[1] &&
             (int64_t)b[0] + b[2] >= (int64_t)vp[0] + vp[2] &&
             (int64_t)b[1] + b[3] >= (int64_t)vp[1] + vp[3]);
}

/* The window rectangle a draw now reaches, x0, y0, x1, y1: the scissor
 * box, and the draw's viewport where it is not the camera's (GL clips
 * each draw to its own viewport; the camera's bounds the picture). False
 * when neither cuts the camera's viewport. */
static bool draw_box(const interp *ip, int64_t r[4])
{
    const gl_attribs *a = &ip->st.a;
    const int32_t *cv = ip->cam_viewport, *vp = a->viewport.rect;
    bool cut = interp_scissor_cuts(ip, cv);
    const int32_t *b = cut ? a->scissor.box : cv;
    r[0] = b[0];
    r[1] = b[1];
    r[2] = (int64_t)b[0] + b[2];
    r[3] = (int64_t)b[1] + b[3];
    if (!ip->frame_begin && memcmp(vp, cv, sizeof ip->cam_viewport) != 0) {
        int64_t v[4] = {vp[0], vp[1], (int64_t)vp[0] + vp[2], (int64_t)vp[1] + vp[3]};
        bool inside = v[0] <= cv[0] && v[1] <= cv[1] && v[2] >= (int64_t)cv[0] + cv[2] &&
                      v[3] >= (int64_t)cv[1] + cv[3];
        for (int k = 0; k < 2 && !inside; k++) {
            r[k] = v[k] > r[k] ? v[k] : r[k];
            r[k + 2] = v[k + 2] < r[k + 2] ? v[k + 2] : r[k + 2];
        }
        cut = cut || !inside;
    }
    return cut;
}

bool interp_scissor_hides(const interp *ip)
{
    int64_t r[4];
    if (!draw_box(ip, r))
        return false;
    const int32_t *cv = ip->cam_viewport;
    return r[2] <= r[0] || r[3] <= r[1] || r[2] <= cv[0] || r[3] <= cv[1] ||
           r[0] >= (int64_t)cv[0] + cv[2] || r[1] >= (int64_t)cv[1] + cv[3];
}

void interp_scissor_look(const interp *ip, scene_look *look)
{
    int64_t r[4];
    if (!draw_box(ip, r))
        return;
    const int32_t *cv = ip->cam_viewport;
    look->scissored = 1;
    look->scissor[0] = (int32_t)(r[0] - cv[0]);
    look->scissor[1] = (int32_t)(r[1] - cv[1]);
    look->scissor[2] = (int32_t)(r[2] > r[0] ? r[2] - r[0] : 0);
    look->scissor[3] = (int32_t)(r[3] > r[1] ? r[3] - r[1] : 0);
}

bool interp_scissor_clear(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    if (!interp_scissor_cuts(ip, a->viewport.rect))
        return false;
    if (s->ntris || s->nlines || s->npoints || s->nsolids || s->ninstances)
        interp_note(ip, DIAG_NOTE_SCISSOR_CLEAR);
    if (a->scissor.box[2] == 0 || a->scissor.box[3] == 0)
        return true;
    if (ip->nclear_rects == INTERP_CLEAR_RECTS) {
        interp_diag(ip, DIAG_LIMIT, "more than %d scissored clears in a frame: the rest are left out",
                    INTERP_CLEAR_RECTS);
        return true;
    }
    struct interp_clear_rect *r = &ip->clear_rects[ip->nclear_rects++];
    memcpy(r->box, a->scissor.box, sizeof r->box);
    memcpy(r->color, a->color_buffer.clear, sizeof r->color);
    return true;
}

/* NDC depth of the rectangles: inside the far plane, behind everything
 * else GL would draw there but a sliver of 1e-6 of the depth range. */
#define CLEAR_DEPTH (1 - 2e-6)

void interp_scissor_end_frame(interp *ip)
{
    scene *s = ip->scene;
    if (!s || ip->nclear_rects == 0)
        return;
    if (!ip->cam_from_ndc_ok) {
        interp_note(ip, DIAG_NOTE_SCISSOR);
        return;
    }
    const int32_t *vp = ip->cam_viewport;
    scene_look look;
    memset(&look, 0, sizeof look);
    look.material = look.texture = -1;
    mat4 id = mat4_identity();
    for (uint32_t i = 0; i < ip->nclear_rects; i++) {
        const struct interp_clear_rect *r = &ip->clear_rects[i];
        /* The box inside the picture. */
        int64_t x0 = r->box[0] > vp[0] ? r->box[0] : vp[0];
        int64_t y0 = r->box[1] > vp[1] ? r->box[1] : vp[1];
        int64_t x1 = (int64_t)r->box[0] + r->box[2], y1 = (int64_t)r->box[1] + r->box[3];
        if (x1 > (int64_t)vp[0] + vp[2])
            x1 = (int64_t)vp[0] + vp[2];
        if (y1 > (int64_t)vp[1] + vp[3])
            y1 = (int64_t)vp[1] + vp[3];
        if (x0 >= x1 || y0 >= y1)
            continue;
        const double corner[4][2] = {{(double)x0, (double)y0}, {(double)x1, (double)y0},
                                     {(double)x1, (double)y1}, {(double)x0, (double)y1}};
        for (int k = 0; k < 4; k++)
            if (!interp_budget_vertex(ip))
                return;
        scene_vertex *v = scene_reserve_vertices(s, 4);
        if (!v)
            return;
        bool ok = true;
        for (int k = 0; k < 4; k++) {
            double in[4] = {corner[k][0], corner[k][1], CLEAR_DEPTH, 1}, o[4];
            mat4_apply(&ip->cam_from_ndc, in, o);
            memset(&v[k], 0, sizeof v[k]);
            for (int c = 0; c < 3; c++) {
                double e = o[3] != 0 ? o[c] / o[3] : NAN;
                ok = ok && isfinite(e) && isfinite((float)e);
                v[k].pos[c] = (float)e;
            }
            v[k].normal[2] = 1;
            for (int c = 0; c < 4; c++)
                v[k].color[c] = clamp01(r->color[c]);
            v[k].color[3] = 1;
        }
        if (!ok)
            continue;
        uint32_t b = (uint32_t)s->nverts;
        scene_commit_vertices(s, 4);
        if (!scene_mesh_for(s, &id, true, &look) || !scene_add_tri(s, b, b + 1, b + 2, b + 2) ||
            !scene_add_tri(s, b, b + 2, b + 3, b + 3))
            return;
    }
}
