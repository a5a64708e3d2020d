/* gltfwrite_light.c: the glTF writer's camera (the scene's, as a glTF
 * camera node) and lights (KHR_lights_punctual, with the extras Blender's
 * import reads: gltfwrite_internal.h).
 */
#include <math.h>
#include <string.h>

#include "gltfwrite_internal.h"

/* ---- the camera ---------------------------------------------------------------------- */

static double light_ref_distance(const scene *s, const double pos[3]);

void gltfw_write_camera(writer *w)
{
    const scene_camera *cam = &w->s->camera;
    double r[3], u[3], fwd[3];
    for (int c = 0; c < 3; c++) {
        r[c] = cam->right[c];
        u[c] = cam->up[c];
    }
    double rl = len3(r), ul = len3(u);
    cross3(u, r, fwd); /* up x right: forward in a right-handed frame */
    double fl = len3(fwd);
    if (!(rl > 0) || !(ul > 0) || !(fl > 0) || !isfinite(rl * ul * fl)) {
        gltfw_note(w, "camera: degenerate; a default camera written");
        r[0] = u[1] = 1;
        r[1] = r[2] = u[0] = u[2] = 0;
        fwd[0] = fwd[1] = 0;
        fwd[2] = -1;
        rl = ul = fl = 1;
    }
    for (int c = 0; c < 3; c++)
        fwd[c] /= fl;
    double focal = dot3(cam->direction, fwd);
    if (focal < 0) /* right x up along the view: a left-handed projection */
        gltfw_note(w, "camera: a mirrored projection; glTF's camera is right-handed, it looks "
                "from the other side (same framing, depth order reversed)");
    /* near and far: where the clip planes cut the axis from location */
    double znear = 0, zfar = 0;
    for (int i = 0; cam->has_clip && i < 2; i++) {
        const double *a = cam->clip[i];
        double af = dot3(a, fwd), t = -(dot3(a, cam->location) + a[3]) / af;
        if (!isfinite(t) || af == 0)
            continue;
        if (af > 0)
            znear = t;
        else
            zfar = t;
    }
    outbuf *o = &w->cameras.ob;
    gltfw_item(&w->cameras);
    if (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC) {
        if (!(zfar > znear)) {
            znear = 0;
            zfar = 1e4;
        }
        outbuf_puts(o, "{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":");
        gltfw_num(o, rl / 2);
        outbuf_puts(o, ",\"ymag\":");
        gltfw_num(o, ul / 2);
        outbuf_puts(o, ",\"znear\":0,\"zfar\":");
        gltfw_num(o, zfar - znear);
        outbuf_puts(o, "}}");
    } else {
        if (!(focal > 0))
            focal = -focal > 0 ? -focal : 1;
        if (!(znear > 0)) /* no near plane (rayglFrameBegin): 1/100 of the scene's distance */
            znear = light_ref_distance(w->s, cam->location) * 0.01;
        double yfov = 2 * atan(ul / 2 / focal);
        outbuf_puts(o, "{\"type\":\"perspective\",\"perspective\":{\"aspectRatio\":");
        gltfw_num(o, rl / ul);
        outbuf_puts(o, ",\"yfov\":");
        gltfw_num(o, yfov);
        outbuf_puts(o, ",\"znear\":");
        gltfw_num(o, znear);
        if (zfar > znear) {
            outbuf_puts(o, ",\"zfar\":");
            gltfw_num(o, zfar);
        }
        outbuf_puts(o, "}}");
        double off[3];
        for (int c = 0; c < 3; c++)
            off[c] = cam->direction[c] - focal * fwd[c];
        if (len3(off) > 1e-6 * focal)
            gltfw_note(w, "camera: an off-axis frustum; glTF's is centred (the image is shifted)");
    }
    double q[4], t[3];
    gltfw_orient(fwd, u, q);
    for (int c = 0; c < 3; c++)
        t[c] = cam->location[c] + (cam->kind == SCENE_CAMERA_ORTHOGRAPHIC ? znear * fwd[c] : 0);
    bool moved = t[0] != 0 || t[1] != 0 || t[2] != 0;
    bool turned = q[0] != 0 || q[1] != 0 || q[2] != 0;
    gltfw_add_node(w, -1, 0, -1, NULL, turned ? q : NULL, moved ? t : NULL, "camera");
}

/* ---- lights ----------------------------------------------------------------------------- */

/* The distance at which a point light's fitted falloff matches GL's: from
 * the light to the centre of the scene's vertices (1 when none). */
static double light_ref_distance(const scene *s, const double pos[3])
{
    double c[3] = {0, 0, 0};
    size_t n = 0;
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *me = &s->meshes[i];
        if (me->proto || me->tri_count == 0 || me->first_tri >= s->ntris ||
            me->look.blend == SCENE_BLEND_INVISIBLE || me->look.alpha_test == SCENE_ALPHA_NEVER)
            continue;
        const scene_tri *t = &s->tris[me->first_tri];
        if (t->v[0] >= s->nverts)
            continue;
        const float *p = s->verts[t->v[0]].pos;
        double in[4] = {p[0], p[1], p[2], 1}, out[4];
        mat4_apply(&me->to_eye, in, out);
        if (!(out[3] != 0) || !isfinite(out[0] + out[1] + out[2] + out[3]))
            continue;
        for (int k = 0; k < 3; k++)
            c[k] += out[k] / out[3];
        n++;
    }
    if (!n)
        return 1;
    double d[3];
    for (int k = 0; k < 3; k++)
        d[k] = c[k] / (double)n - pos[k];
    double l = len3(d);
    return l > 1e-6 && isfinite(l) ? l : 1;
}

/* A light's soft shadow as Blender takes it (tools/blender/raygl-blender.py
 * reads the light's extras): an added area light (--light area) as a
 * sphere of its mean half extent; with --area-lights, the GL lights as
 * POV-Ray's discs a tenth of their distance to the scene's centre across
 * (a sun: the angle such a disc spans). 0: a point, casting no shadow. */
static double light_soft_size(const scene *s, const scene_light *l, const double pos[3])
{
    if (l->added && l->area_samples[0] > 0)
        return (len3(l->area_axis[0]) + len3(l->area_axis[1])) / 4;
    if (l->aimed || s->options.area_lights < 2 || s->options.no_shadows)
        return 0;
    if (l->kind == SCENE_LIGHT_PARALLEL)
        return 2 * atan(0.05);
    return 0.05 * light_ref_distance(s, pos);
}

void gltfw_write_lights(writer *w)
{
    const scene *s = w->s;
    bool other_sets = false, attenuated = false, soft_shadows = false;
    for (size_t i = 0; i < s->nlights; i++) {
        const scene_light *l = &s->lights[i];
        if (!l->aimed && l->set != 0) {
            other_sets = true;
            continue; /* glTF lights light everything: the first set only */
        }
        double col[3], mx = 0;
        for (int c = 0; c < 3; c++) {
            col[c] = gltfw_srgb_linear(l->color[c]);
            mx = col[c] > mx ? col[c] : mx;
        }
        if (!(mx > 0))
            continue;
        for (int c = 0; c < 3; c++)
            col[c] /= mx;
        /* A spec-following viewer's Lambert term is colour * intensity *
         * cos / pi times the base colour: pi makes GL's diffuse. */
        double inten = mx * GLTF_PI;
        bool directional = l->kind == SCENE_LIGHT_PARALLEL;
        double pos[3] = {0, 0, 0}, fwd[3] = {0, 0, -1}, up[3] = {0, 1, 0};
        if (directional) {
            if (l->aimed)
                for (int c = 0; c < 3; c++)
                    fwd[c] = l->point_at[c] - l->position[c];
            else
                for (int c = 0; c < 3; c++)
                    fwd[c] = -l->direction[c];
        } else {
            for (int c = 0; c < 3; c++) {
                pos[c] = l->position[c];
                if (l->kind == SCENE_LIGHT_SPOT)
                    fwd[c] = l->direction[c];
            }
            /* glTF's falloff is 1/d^2, GL's 1/(kc + kl d + kq d^2): equal at
             * the distance of the scene's centre. */
            double d = light_ref_distance(s, pos);
            double att = l->attenuation[0] + l->attenuation[1] * d + l->attenuation[2] * d * d;
            if (!(att > 1e-9) || !isfinite(att))
                att = 1;
            inten *= d * d / att;
            attenuated = true;
        }
        if (fabs(fwd[0]) < 1e-9 && fabs(fwd[2]) < 1e-9)
            up[1] = 0, up[2] = 1;
        size_t k = gltfw_item(&w->lights);
        outbuf *o = &w->lights.ob;
        outbuf_puts(o, "{\"type\":\"");
        outbuf_puts(o, directional ? "directional" : l->kind == SCENE_LIGHT_SPOT ? "spot" : "point");
        outbuf_puts(o, "\",\"color\":");
        gltfw_nums(o, col, 3);
        outbuf_puts(o, ",\"intensity\":");
        gltfw_num(o, inten);
        if (l->kind == SCENE_LIGHT_SPOT) {
            double outer = l->spot_cutoff * GLTF_PI / 180, e = l->spot_exponent;
            if (!(outer > 0) || outer > GLTF_PI / 2)
                outer = GLTF_PI / 2;
            /* GL's cos^e falls to half at acos(2^(-1/e)): glTF's ramp from
             * inner to outer is centred there (a hard edge for e = 0). */
            double inner = outer * 0.95;
            if (e > 0) {
                double half = acos(pow(0.5, 1 / e));
                inner = 2 * half - outer;
                if (inner > outer * 0.95)
                    inner = outer * 0.95;
                if (inner < 0)
                    inner = 0;
            }
            outbuf_puts(o, ",\"spot\":{\"innerConeAngle\":");
            gltfw_num(o, inner);
            outbuf_puts(o, ",\"outerConeAngle\":");
            gltfw_num(o, outer);
            outbuf_putc(o, '}');
        }
        double soft = light_soft_size(s, l, pos);
        if (soft > 0) {
            outbuf_puts(o, directional ? ",\"extras\":{\"rayglShadowAngle\":"
                                       : ",\"extras\":{\"rayglShadowRadius\":");
            gltfw_num(o, soft);
            outbuf_putc(o, '}');
            soft_shadows = true;
        }
        outbuf_putc(o, '}');
        double q[4];
        gltfw_orient(fwd, up, q);
        bool turned = q[0] != 0 || q[1] != 0 || q[2] != 0;
        bool moved = pos[0] != 0 || pos[1] != 0 || pos[2] != 0;
        gltfw_add_node(w, -1, -1, (long)k, NULL, turned ? q : NULL, moved ? pos : NULL, NULL);
        w->used_lights = true;
        w->st.lights++;
    }
    if (other_sets)
        gltfw_note(w, "lights: draws under other GL lights; only the first draw's lights written");
    if (attenuated)
        gltfw_note(w, "lights: GL's attenuation fitted as 1/d^2 at the scene's centre");
    if (soft_shadows)
        gltfw_note(w, "area lights: glTF's lights are points; their size is kept in the lights' extras "
                "(rayglShadowRadius, rayglShadowAngle), for Blender's soft shadows");
}
