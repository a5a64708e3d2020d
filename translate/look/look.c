/* look.c: the look step (look.h): size, camera, lights and the scene's
 * options, applied to a built scene. */
#include "look.h"

#include <math.h>
#include <string.h>

#include "talloc.h"

#define PI 3.14159265358979323846

void look_free(look_settings *l)
{
    tr_free(l->lights);
    tr_free(l->includes);
    memset(l, 0, sizeof *l);
}

bool look_overrides_camera(const look_settings *l)
{
    return l->has_location || l->has_look_at || l->has_up || l->has_fov || l->orthographic;
}

static bool normalize3(double v[3])
{
    double n = sqrt(dot3(v, v));
    if (!(n > 1e-12) || !isfinite(n))
        return false;
    for (int k = 0; k < 3; k++)
        v[k] /= n;
    return true;
}

static void xform(const mat4 *m, const double in[3], double w, double out[3])
{
    double a[4] = {in[0], in[1], in[2], w}, b[4];
    mat4_apply(m, a, b);
    if (w != 0 && b[3] != 0 && b[3] != 1)
        for (int k = 0; k < 3; k++)
            b[k] /= b[3];
    memcpy(out, b, 3 * sizeof *out);
}

/* World -> eye for the overrides; false when they are in eye space. */
static bool override_view(const look_settings *l, const scene *s, mat4 *view, mat4 *inv)
{
    if (l->eye_space || !s->have_view || !mat4_finite(&s->view) || !mat4_affine(&s->view) ||
        !mat4_invert(&s->view, inv))
        return false;
    *view = s->view;
    return true;
}

static void apply_size(const look_settings *l, scene *s)
{
    scene_camera *c = &s->camera;
    int w0 = c->width > 0 ? c->width : 1, h0 = c->height > 0 ? c->height : 1;
    int w = w0, h = h0;
    if (l->width && l->height) {
        w = l->width;
        h = l->height;
    } else if (l->width) {
        w = l->width;
        h = (int)fmax(1, floor((double)w * h0 / w0 + 0.5));
    } else if (l->height) {
        h = l->height;
        w = (int)fmax(1, floor((double)h * w0 / h0 + 0.5));
    }
    if (w > LOOK_MAX_SIZE)
        w = LOOK_MAX_SIZE;
    if (h > LOOK_MAX_SIZE)
        h = LOOK_MAX_SIZE;
    /* A new aspect keeps the vertical extent and widens or narrows the view,
     * as a GL program does when its window is resized. */
    double k = ((double)w / h) / ((double)w0 / h0);
    for (int i = 0; i < 3; i++)
        c->right[i] *= k;
    c->width = w;
    c->height = h;
}

static void grow_box(double lo[3], double hi[3], const mat4 *m, const float p[3])
{
    double e[3], in[3] = {p[0], p[1], p[2]};
    if (m)
        xform(m, in, 1, e);
    else
        memcpy(e, in, sizeof e);
    for (int k = 0; k < 3; k++)
        if (isfinite(e[k])) {
            lo[k] = fmin(lo[k], e[k]);
            hi[k] = fmax(hi[k], e[k]);
        }
}

static void box_mesh(const scene *s, const scene_mesh *me, const mat4 *place, double lo[3],
                     double hi[3])
{
    mat4 m = me->in_eye ? mat4_identity() : me->to_eye;
    if (place)
        m = mat4_mul(place, &m);
    for (size_t t = me->first_tri; t < me->first_tri + me->tri_count && t < s->ntris; t++)
        for (int c = 0; c < 3; c++)
            if (s->tris[t].v[c] < s->nverts)
                grow_box(lo, hi, &m, s->verts[s->tris[t].v[c]].pos);
}

/* The point an orthographic override frames as the perspective view framed
 * it, in the overrides' coordinates: the frame's gluLookAt centre, or the
 * centre of the eye-space box of what the frame drew. False: nothing drawn. */
static bool focus_point(const scene *s, bool world, double out[3])
{
    if (s->have_view) {
        if (world)
            memcpy(out, s->view_look_at, 3 * sizeof *out);
        else
            xform(&s->view, s->view_look_at, 1, out);
        return true;
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->nmeshes; i++)
        if (!s->meshes[i].proto)
            box_mesh(s, &s->meshes[i], NULL, lo, hi);
    for (size_t i = 0; i < s->ninstances; i++) {
        const scene_instance *in = &s->instances[i];
        if (in->proto >= s->nprotos)
            continue;
        const scene_proto *pr = &s->protos[in->proto];
        for (size_t k = pr->first_mesh; k < pr->first_mesh + pr->nmeshes && k < s->nmeshes; k++)
            box_mesh(s, &s->meshes[k], &in->to_eye, lo, hi);
    }
    static const float origin[3] = {0, 0, 0};
    for (size_t i = 0; i < s->nsolids; i++)
        grow_box(lo, hi, &s->solids[i].to_eye, origin);
    for (size_t i = 0; i < s->nlines; i++)
        for (int e = 0; e < 2; e++)
            grow_box(lo, hi, NULL, s->lines[i].p[e]);
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]))
        return false;
    for (int k = 0; k < 3; k++)
        out[k] = (lo[k] + hi[k]) / 2;
    return true;
}

static void apply_camera(const look_settings *l, scene *s, bool world, const mat4 *view,
                         const mat4 *inv)
{
    scene_camera *c = &s->camera;
    double loc[3], dir[3], up[3];
    if (world) {
        xform(inv, c->location, 1, loc);
        xform(inv, c->direction, 0, dir);
        xform(inv, c->up, 0, up);
    } else {
        memcpy(loc, c->location, sizeof loc);
        memcpy(dir, c->direction, sizeof dir);
        memcpy(up, c->up, sizeof up);
    }
    /* The original camera's vertical field of view and view height. */
    double ul = sqrt(dot3(c->up, c->up)), dl = sqrt(dot3(c->direction, c->direction));
    bool was_ortho = c->kind == SCENE_CAMERA_ORTHOGRAPHIC;
    double fov = !was_ortho && dl > 0 ? 2 * atan(ul / 2 / dl) * 180 / PI : 45;
    if (!(fov > 0 && fov < 180))
        fov = 45;
    if (l->has_fov)
        fov = l->fov;

    double L[3], T[3], U[3], f[3], r[3], u[3];
    memcpy(L, l->has_location ? l->location : loc, sizeof L);
    if (l->has_look_at) {
        memcpy(T, l->look_at, sizeof T);
    } else {
        double d[3] = {dir[0], dir[1], dir[2]};
        if (!normalize3(d))
            d[0] = 0, d[1] = 0, d[2] = -1;
        for (int k = 0; k < 3; k++)
            T[k] = L[k] + d[k];
    }
    memcpy(U, l->has_up ? l->up : up, sizeof U);
    for (int k = 0; k < 3; k++)
        f[k] = T[k] - L[k];
    double dist = sqrt(dot3(f, f));
    if (!normalize3(f)) {
        f[0] = f[1] = 0;
        f[2] = -1;
        dist = 1;
    }
    cross3(f, U, r);
    if (!normalize3(r)) {
        /* Looking along the up vector: any perpendicular will do. */
        double a[3] = {fabs(f[0]) < 0.9 ? 1 : 0, fabs(f[0]) < 0.9 ? 0 : 1, 0};
        cross3(f, a, r);
        normalize3(r);
    }
    cross3(r, f, u);
    /* An orthographic view from a perspective one, without a look-at
     * point: framed at the depth of what the frame looked at. */
    double fp[3];
    if (l->orthographic && !l->has_look_at && !(was_ortho && !l->has_fov) &&
        focus_point(s, world, fp)) {
        double d = (fp[0] - L[0]) * f[0] + (fp[1] - L[1]) * f[1] + (fp[2] - L[2]) * f[2];
        if (d > 0 && isfinite(d))
            dist = d;
    }
    double aspect = (double)c->width / (c->height > 0 ? c->height : 1);
    double height = 1, dlen = 0.5 / tan(fov * PI / 360);
    if (l->orthographic) {
        /* The view height at the look-at distance: the perspective view's
         * framing there, or the original orthographic height. */
        height = was_ortho && !l->has_fov ? ul : 2 * dist * tan(fov * PI / 360);
        if (world && was_ortho && !l->has_fov) {
            double uw[3];
            xform(inv, c->up, 0, uw);
            height = sqrt(dot3(uw, uw));
        }
        dlen = 1;
    }
    double wl[3], wr[3], wu[3], wd[3];
    for (int k = 0; k < 3; k++) {
        wl[k] = L[k];
        wd[k] = f[k] * dlen;
        wu[k] = u[k] * height;
        wr[k] = r[k] * height * aspect;
    }
    scene_camera n;
    memset(&n, 0, sizeof n);
    n.kind = l->orthographic ? SCENE_CAMERA_ORTHOGRAPHIC : SCENE_CAMERA_PERSPECTIVE;
    n.width = c->width;
    n.height = c->height;
    if (world) {
        xform(view, wl, 1, n.location);
        xform(view, wd, 0, n.direction);
        xform(view, wu, 0, n.up);
        xform(view, wr, 0, n.right);
    } else {
        memcpy(n.location, wl, sizeof wl);
        memcpy(n.direction, wd, sizeof wd);
        memcpy(n.up, wu, sizeof wu);
        memcpy(n.right, wr, sizeof wr);
    }
    /* GL's near and far planes belong to the old camera. */
    n.has_clip = false;
    *c = n;
}

/* The two axes of an area light across the direction from at to `to`,
 * sized in the override's space; the light faces its target. */
static void area_axes(const look_light *L, double a[3], double b[3])
{
    double f[3] = {L->to[0] - L->at[0], L->to[1] - L->at[1], L->to[2] - L->at[2]};
    double up[3] = {0, 1, 0};
    if (!normalize3(f))
        f[0] = 0, f[1] = -1, f[2] = 0;
    cross3(f, up, a);
    if (!normalize3(a)) {
        double x[3] = {1, 0, 0};
        cross3(f, x, a);
        normalize3(a);
    }
    cross3(a, f, b);
    for (int k = 0; k < 3; k++) {
        a[k] *= L->size[0];
        b[k] *= L->size[1];
    }
}

/* Light L as a scene light in eye space. */
static int add_light(const look_light *L, scene *s, bool world, const mat4 *view)
{
    scene_light *sl = scene_add_light(s);
    if (!sl)
        return -1;
    double at[3], to[3];
    if (world) {
        xform(view, L->at, 1, at);
        xform(view, L->to, 1, to);
    } else {
        memcpy(at, L->at, sizeof at);
        memcpy(to, L->to, sizeof to);
    }
    /* An area light is a point at its centre with its extent beside: a
     * writer without area lights keeps its brightness and place. */
    sl->kind = L->kind == LOOK_LIGHT_PARALLEL ? SCENE_LIGHT_PARALLEL
               : L->kind == LOOK_LIGHT_SPOT   ? SCENE_LIGHT_SPOT
                                              : SCENE_LIGHT_POINT;
    sl->aimed = true; /* lights everything, as POV-Ray's added lights do */
    sl->added = true;
    for (int k = 0; k < 3; k++) {
        sl->position[k] = at[k];
        sl->point_at[k] = to[k];
        sl->direction[k] = to[k] - at[k];
        sl->color[k] = (float)L->color[k];
    }
    sl->spot_cutoff = (float)(L->kind == LOOK_LIGHT_SPOT ? L->falloff : 180);
    sl->spot_radius = (float)L->radius;
    /* POV-Ray's full-intensity radius as GL's exponent whose falloff is
     * half way down midway between radius and falloff */
    double mid = (L->radius + L->falloff) / 2 * PI / 180;
    if (L->kind == LOOK_LIGHT_SPOT && L->radius < L->falloff && mid > 0 && cos(mid) > 0)
        sl->spot_exponent = (float)(log(0.5) / log(cos(mid)));
    sl->attenuation[0] = 1; /* POV-Ray's lights do not fade */
    if (L->kind == LOOK_LIGHT_AREA) {
        double a[3], b[3];
        area_axes(L, a, b);
        if (world) {
            xform(view, a, 0, sl->area_axis[0]);
            xform(view, b, 0, sl->area_axis[1]);
        } else {
            memcpy(sl->area_axis[0], a, sizeof a);
            memcpy(sl->area_axis[1], b, sizeof b);
        }
        sl->area_samples[0] = L->samples[0];
        sl->area_samples[1] = L->samples[1];
    }
    return 0;
}

int look_apply(const look_settings *l, scene *s, const char **note)
{
    apply_size(l, s);
    mat4 view, inv;
    bool world = override_view(l, s, &view, &inv);
    if (look_overrides_camera(l))
        apply_camera(l, s, world, &view, &inv);
    if (l->no_gl_lights)
        s->nlights = 0;
    s->options = l->options;
    s->options.world_view = world;
    *note = NULL;
    if (look_overrides_camera(l) || l->nlights > 0) {
        if (world)
            *note = "camera and light overrides are in world coordinates (the frame's gluLookAt)";
        else if (s->camera.kind != SCENE_CAMERA_LOOKAT)
            *note = "camera and light overrides are in eye coordinates (no gluLookAt in the frame)";
    }
    for (size_t i = 0; i < l->nlights; i++)
        if (add_light(&l->lights[i], s, world, &view) != 0)
            return -1;
    return 0;
}
