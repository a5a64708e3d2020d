/* interp_raster.c: clear and background, shading and face state, point
 * and line size, the per-fragment state, the frame calls (glutSwapBuffers,
 * rayglFrameBegin/End), and the frame's camera.
 *
 * The camera is fixed by the frame's first draw: the projection and
 * viewport current then (or rayglFrameBegin's look-at camera, or the 3D
 * scene's projection preset by interp_proj.c). Draws made
 * later with another projection or viewport are remapped into it (see
 * setup_transform in interp_prim.c). A glClear of the colour buffer erases
 * what was drawn before it, as in GL, and sets the background.
 */
#include "interp_internal.h"

#include <string.h>

/* ---- The frame ---------------------------------------------------------------- */

void interp_fix_camera(interp *ip)
{
    scene *s = ip->scene;
    if (ip->camera_fixed || !s)
        return;
    ip->camera_fixed = true;
    s->have_camera = true;
    const gl_attribs *a = &ip->st.a;
    /* A second translation of a frame of several projections: the 3D
     * scene's camera, chosen by the first (interp_proj.c). */
    const mat4 *proj = ip->cam_preset ? &ip->cam_preset_proj : interp_matrix(ip, INTERP_PROJ);
    memcpy(ip->own_vp, ip->cam_preset ? ip->cam_preset_vp : a->viewport.rect, sizeof ip->own_vp);
    ip->own_proj = *proj;
    memcpy(ip->cam_viewport, ip->own_vp, sizeof ip->cam_viewport);
    ip->cam_proj = *proj;

    if (ip->frame_begin) {
        /* The paper's camera; its field of view comes from the GL
         * projection when that is a perspective one (p5 = cot(fovy/2)). */
        double fovy = 0;
        if (proj->m[11] != 0 && proj->m[15] == 0 && proj->m[5] != 0 && isfinite(proj->m[5]))
            fovy = 2 * atan(fabs(1 / proj->m[5])) * 180 / 3.14159265358979323846;
        scene_camera_lookat(&s->camera, ip->fb_loc, ip->fb_look, fovy, a->viewport.rect[2],
                            a->viewport.rect[3]);
        ip->cam_from_ndc_ok = false;
        return;
    }
    interp_proj_widen_camera(ip);
    if (!scene_camera_from_gl(&s->camera, &ip->cam_proj, ip->cam_viewport))
        interp_note(ip, DIAG_NOTE_CAMERA);
    mat4 w = interp_window_matrix(&ip->cam_proj, ip->cam_viewport);
    ip->cam_from_ndc_ok = mat4_invert(&w, &ip->cam_from_ndc);
}

void interp_begin_frame(interp *ip)
{
    if (ip->in_begin)
        interp_abort_begin(ip);
    ip->camera_fixed = false;
    ip->frame_begin = false;
    ip->frame_name[0] = '\0';
    interp_clear_notes(ip);
    ip->cleared = false;
    ip->painter = 0;
    ip->shape_facets = 0;
    ip->segments = 0;
    ip->pixels_mark = 0;
    ip->raster_pre = ip->raster_pre_mixed = false;
    ip->nclear_rects = 0;
    interp_proj_begin_frame(ip);
    interp_zorder_begin_frame(ip);
    unrec_clear(&ip->unrecorded);
    interp_accum_begin_frame(ip);
    interp_bounds_begin_frame(ip);
    if (ip->scene)
        scene_reset(ip->scene);
    interp_lists_begin_frame(ip);
    interp_texture_begin_frame(ip);
    interp_pixels_begin_frame(ip);
    /* the scene's stencil region starts empty (interp_stencil.c) */
    ip->stencil.first = 0;
    ip->stencil.written = ip->stencil.mixed = ip->stencil.box_pending = false;
}

void interp_end_frame(interp *ip)
{
    scene *s = ip->scene;
    if (ip->in_begin && ip->cut) {
        interp_abort_begin(ip); /* the cut stopped it, not the trace */
    } else if (ip->in_begin) {
        interp_diag(ip, DIAG_IGNORED, "frame ends inside glBegin: the open primitive is dropped");
        interp_abort_begin(ip);
    }
    if (!s)
        return;
    interp_budget_peak(ip);
    interp_fix_camera(ip);
    interp_proj_end_frame(ip);
    interp_zorder_end_frame(ip);
    interp_pixels_end_frame(ip);
    interp_dest_end_frame(ip);
    interp_scissor_end_frame(ip);
    if (!ip->cleared)
        for (int i = 0; i < 4; i++)
            s->background[i] = clamp01(ip->st.a.color_buffer.clear[i]);
    if (ip->frame_begin) {
        /* rayglFrameBegin's white parallel light, aimed at the look-at point. */
        scene_light *l = scene_add_light(s);
        if (l) {
            l->kind = SCENE_LIGHT_PARALLEL;
            l->aimed = true;
            l->spot_cutoff = 180;
            l->attenuation[0] = 1;
            l->specular[0] = l->specular[1] = l->specular[2] = 1;
            for (int k = 0; k < 3; k++) {
                l->position[k] = isfinite(ip->fb_light[k]) ? ip->fb_light[k] : 0;
                l->point_at[k] = s->camera.look_at[k];
            }
            l->color[0] = l->color[1] = l->color[2] = 1;
        }
    }
}

void interp_swapbuffers(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_frameend(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
/* The image the program showed: nothing to draw (raygl-compare reads it). */
void interp_snapshot(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

/* A call the recorder passed to GL unrecorded (docs/format.md 3.2): said,
 * since the frame may lack what it did. */
void interp_skipped(interp *ip, const rgl_cmd *cmd)
{
    const rgl_cmd_info *call = rgl_cmd_info_get((uint32_t)cmd->arg[0].v.u);
    uint64_t reason = cmd->arg[1].v.u;
    interp_diag(ip, DIAG_IGNORED, "%s was not recorded: %s", call ? call->name : "a call",
                reason == RGL_SKIP_UNKNOWN_ENUM ? "an enum the recorder does not know"
                : reason == RGL_SKIP_NO_DATA    ? "its data could not be read"
                                                : "unknown reason");
}

void interp_framebegin(interp *ip, const rgl_cmd *cmd)
{
    const rgl_arg *name = &cmd->arg[0];
    size_t n = name->count < RGL_STRING_MAX ? name->count : RGL_STRING_MAX;
    for (size_t i = 0; i < n; i++)
        ip->frame_name[i] = name->bytes[i] ? (char)name->bytes[i] : '_';
    ip->frame_name[n] = '\0';
    for (int k = 0; k < 3; k++) {
        ip->fb_loc[k] = arg_num(&cmd->arg[1 + k]);
        ip->fb_look[k] = arg_num(&cmd->arg[4 + k]);
        ip->fb_light[k] = arg_num(&cmd->arg[7 + k]);
    }
    ip->frame_begin = true;
    ip->camera_fixed = false; /* the look-at camera replaces any GL one */
}

/* ---- Clearing ---------------------------------------------------------------- */

void interp_clearcolor(interp *ip, const rgl_cmd *cmd)
{
    for (int i = 0; i < 4; i++)
        ip->st.a.color_buffer.clear[i] = clamp01((float)arg_num(&cmd->arg[i]));
}

void interp_cleardepth(interp *ip, const rgl_cmd *cmd)
{
    double d = arg_num(&cmd->arg[0]);
    ip->st.a.depth.clear = d > 0 ? (d < 1 ? d : 1) : 0;
}

void interp_clear(interp *ip, const rgl_cmd *cmd)
{
    uint32_t mask = (uint32_t)cmd->arg[0].v.u;
    const uint32_t known = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT |
                           GL_ACCUM_BUFFER_BIT;
    if (mask & ~known) {
        interp_bad_value(ip, "glClear mask has unknown bits");
        return;
    }
    /* A colour clear of a buffer the frame does not show leaves its
     * picture alone (interp_buffers.c); depth and stencil are shared. The
     * write masks apply to the clear (GL 1.x 4.2.3): with red, green and
     * blue masked it changes no colour, under glDepthMask(GL_FALSE) no
     * depth. */
    const gl_attribs *a = &ip->st.a;
    const bool *cm = a->color_buffer.mask;
    if ((mask & GL_COLOR_BUFFER_BIT) && (interp_draw_buffer_hidden(ip) || (!cm[0] && !cm[1] && !cm[2])))
        mask &= ~(uint32_t)GL_COLOR_BUFFER_BIT;
    if (!a->depth.mask)
        mask &= ~(uint32_t)GL_DEPTH_BUFFER_BIT;
    /* A depth clear the scissor box cuts starts no part of the frame in
     * front of the earlier ones: outside the box GL keeps their depth
     * (conf_scissor_clear_depth; NOTE_DEPTH_CLEAR says what differs). */
    if ((mask & GL_DEPTH_BUFFER_BIT) && !(mask & GL_COLOR_BUFFER_BIT) &&
        ip->st.render_mode == GL_RENDER &&
        !(a->caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_cuts(ip, a->viewport.rect)))
        interp_proj_depth_clear(ip);
    if ((mask & GL_DEPTH_BUFFER_BIT) && ip->st.render_mode == GL_RENDER && ip->st.a.depth.mask &&
        !((mask & GL_COLOR_BUFFER_BIT) && !interp_scissor_cuts(ip, ip->st.a.viewport.rect)))
        interp_dest_depth_clear(ip);
    if ((mask & GL_ACCUM_BUFFER_BIT) && ip->st.render_mode == GL_RENDER)
        interp_accum_buffer_clear(ip);
    if ((mask & GL_STENCIL_BUFFER_BIT) && ip->st.render_mode == GL_RENDER) {
        if (ip->st.a.caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_cuts(ip, ip->st.a.viewport.rect))
            interp_stencil_clear_box(ip);
        else
            interp_stencil_clear(ip);
    }
    if (!(mask & GL_COLOR_BUFFER_BIT) || !ip->scene || ip->st.render_mode != GL_RENDER)
        return;
    if ((!cm[0] || !cm[1] || !cm[2]) &&
        !(a->caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_cuts(ip, a->viewport.rect)) &&
        !(mask & GL_DEPTH_BUFFER_BIT) && interp_masks_clear(ip))
        return; /* the unmasked channels of what is there recoloured */
    if (!cm[0] || !cm[1] || !cm[2])
        interp_note(ip, DIAG_NOTE_CLEAR_COLOR_MASK); /* cleared whole */
    if (a->caps[INTERP_CAP_SCISSOR_TEST] && interp_scissor_clear(ip)) {
        interp_proj_window_add(ip);
        return; /* a partial clear: what is drawn stays */
    }
    if (interp_accum_clear(ip))
        return;
    interp_proj_clear(ip);
    interp_proj_window_add(ip);
    /* Everything drawn so far is gone; the next draw fixes the camera anew. */
    interp_budget_peak(ip);
    scene_clear_geometry(ip->scene);
    ip->nclear_rects = 0;
    ip->camera_fixed = false;
    ip->cleared = true;
    ip->painter = 0;
    for (int i = 0; i < 4; i++)
        ip->scene->background[i] = a->color_buffer.clear[i];
}

/* ---- Shading, faces, sizes ------------------------------------------------------ */

void interp_shademodel(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0);
    if (m != GL_FLAT && m != GL_SMOOTH) {
        interp_bad_enum(ip, "shade model", m);
        return;
    }
    ip->st.a.lighting.shade_model = m;
}

void interp_frontface(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0);
    if (m != GL_CW && m != GL_CCW) {
        interp_bad_enum(ip, "front face", m);
        return;
    }
    ip->st.a.polygon.front_face = m;
}

static bool is_face(GLenum f) { return f == GL_FRONT || f == GL_BACK || f == GL_FRONT_AND_BACK; }

void interp_cullface(interp *ip, const rgl_cmd *cmd)
{
    GLenum m = arg_enum(cmd, 0);
    if (!is_face(m)) {
        interp_bad_enum(ip, "cull face", m);
        return;
    }
    ip->st.a.polygon.cull_mode = m;
}

void interp_polygonmode(interp *ip, const rgl_cmd *cmd)
{
    GLenum face = arg_enum(cmd, 0), mode = arg_enum(cmd, 1);
    if (!is_face(face)) {
        interp_bad_enum(ip, "face", face);
        return;
    }
    if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
        interp_bad_enum(ip, "polygon mode", mode);
        return;
    }
    if (face != GL_BACK)
        ip->st.a.polygon.mode[0] = mode;
    if (face != GL_FRONT)
        ip->st.a.polygon.mode[1] = mode;
}

void interp_pointsize(interp *ip, const rgl_cmd *cmd)
{
    double v = arg_num(&cmd->arg[0]);
    if (!(v > 0) || !isfinite(v)) {
        interp_bad_value(ip, "point size not positive");
        return;
    }
    ip->st.a.point.size = (float)fmin(v, 1024); /* Mesa's largest point */
}

void interp_linewidth(interp *ip, const rgl_cmd *cmd)
{
    double v = arg_num(&cmd->arg[0]);
    if (!(v > 0) || !isfinite(v)) {
        interp_bad_value(ip, "line width not positive");
        return;
    }
    ip->st.a.line.width = (float)fmin(v, 1024);
}

void interp_polygonoffset(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.polygon.offset_factor = (float)arg_num(&cmd->arg[0]);
    ip->st.a.polygon.offset_units = (float)arg_num(&cmd->arg[1]);
}

/* ---- Per-fragment state (blending: interp_blend.c) ----------------------------- */

static bool is_compare(GLenum f) { return f >= GL_NEVER && f <= GL_ALWAYS; }

void interp_alphafunc(interp *ip, const rgl_cmd *cmd)
{
    GLenum f = arg_enum(cmd, 0);
    if (!is_compare(f)) {
        interp_bad_enum(ip, "alpha function", f);
        return;
    }
    ip->st.a.color_buffer.alpha_func = f;
    ip->st.a.color_buffer.alpha_ref = clamp01((float)arg_num(&cmd->arg[1]));
}

void interp_depthfunc(interp *ip, const rgl_cmd *cmd)
{
    GLenum f = arg_enum(cmd, 0);
    if (!is_compare(f)) {
        interp_bad_enum(ip, "depth function", f);
        return;
    }
    ip->st.a.depth.func = f;
}

void interp_depthmask(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.depth.mask = cmd->arg[0].v.u != 0;
}

void interp_colormask(interp *ip, const rgl_cmd *cmd)
{
    for (int i = 0; i < 4; i++)
        ip->st.a.color_buffer.mask[i] = cmd->arg[i].v.u != 0;
}
