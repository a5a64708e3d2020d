/* look.c: size, camera, light, quality and include overrides (look.h). */
#include "look.h"

#include <errno.h>
#include <fcntl.h>
#include <locale.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "options.h"
#include "talloc.h"

#define LOOK_MAX_SIZE 65536
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

/* ---- Values ---------------------------------------------------------------------------- */

/* A number in C notation whatever the locale (the user's locale is on for
 * messages: strtod alone would read "0,5" in de_DE). */
static bool parse_num(const char *s, const char **end, double *out)
{
    static locale_t c_locale;
    if (!c_locale)
        c_locale = newlocale(LC_ALL_MASK, "C", (locale_t)0);
    if (!c_locale)
        return false;
    char *e;
    errno = 0;
    double v = strtod_l(s, &e, c_locale);
    if (e == s || errno == ERANGE || !isfinite(v) || *s == ' ')
        return false;
    *end = e;
    *out = v;
    return true;
}

/* "X,Y,Z" (n numbers separated by commas). */
static bool parse_vec(const char *s, double *v, int n, const char **end)
{
    for (int i = 0; i < n; i++) {
        if (!parse_num(s, &s, &v[i]))
            return false;
        if (i + 1 < n) {
            if (*s != ',')
                return false;
            s++;
        }
    }
    *end = s;
    return true;
}

static bool set_vec(double *v, bool *has, const char *value, const opt_ctx *ctx, opt_err *err)
{
    const char *e;
    if (!parse_vec(value, v, 3, &e) || *e)
        return opt_fail(err, "%s '%s': expected three numbers X,Y,Z", ctx->option, value);
    *has = true;
    return true;
}

static bool set_size(int *v, const char *value, const opt_ctx *ctx, opt_err *err)
{
    char *e;
    long n = strtol(value, &e, 10);
    if (e == value || *e || n < 1 || n > LOOK_MAX_SIZE || value[0] == '-' || value[0] == '+' ||
        value[0] == ' ')
        return opt_fail(err, "%s '%s': expected a size in pixels from 1 to %d", ctx->option,
                        value, LOOK_MAX_SIZE);
    *v = (int)n;
    return true;
}

bool opt_set_width(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_size(&o->look.width, v, ctx, err);
}

bool opt_set_height(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_size(&o->look.height, v, ctx, err);
}

bool opt_set_camera_location(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_vec(o->look.location, &o->look.has_location, v, ctx, err);
}

bool opt_set_camera_look_at(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return set_vec(o->look.look_at, &o->look.has_look_at, v, ctx, err);
}

bool opt_set_camera_up(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (!set_vec(o->look.up, &o->look.has_up, v, ctx, err))
        return false;
    const double *u = o->look.up;
    if (u[0] == 0 && u[1] == 0 && u[2] == 0)
        return opt_fail(err, "%s '%s': the up vector cannot be zero", ctx->option, v);
    return true;
}

bool opt_set_camera_fov(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    const char *e;
    double d;
    if (!parse_num(v, &e, &d) || *e || !(d > 0 && d < 180))
        return opt_fail(err, "%s '%s': expected an angle in degrees between 0 and 180",
                        ctx->option, v);
    o->look.fov = d;
    o->look.has_fov = true;
    return true;
}

bool opt_set_camera_orthographic(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.orthographic, ctx, err);
}

bool opt_set_override_space(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    if (strcmp(v, "auto") == 0)
        o->look.eye_space = false;
    else if (strcmp(v, "eye") == 0)
        o->look.eye_space = true;
    else
        return opt_fail(err, "%s '%s': expected auto or eye", ctx->option, v);
    return true;
}

bool opt_set_no_gl_lights(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.no_gl_lights, ctx, err);
}

bool opt_set_antialias(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.antialias, ctx, err);
}

bool opt_set_radiosity(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    return opt_bool(v, &o->look.radiosity, ctx, err);
}

bool opt_set_quality(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    char *e;
    long n = strtol(v, &e, 10);
    if (e == v || *e || n < 0 || n > 11 || v[0] == ' ' || v[0] == '+')
        return opt_fail(err, "%s '%s': expected a POV-Ray quality from 0 to 11", ctx->option, v);
    o->look.quality = n == 0 ? -1 : (int)n; /* -1: Quality=0 asked for */
    o->pov.quick = n < 6; /* POV-Ray's quick colours: no image maps */
    return true;
}

bool opt_set_preview(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    bool on;
    if (!opt_bool(v, &on, ctx, err))
        return false;
    if (on) { /* quality 4: no reflections, media, image maps; no shadows here */
        o->look.quality = 4;
        o->pov.quick = true;
        o->pov.no_shadows = true;
    }
    return true;
}

bool opt_set_include(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    look_settings *l = &o->look;
    const char *path = opt_path(o, v, ctx, err);
    if (!path)
        return false;
    struct stat st;
    if (stat(path, &st) != 0)
        return opt_fail(err, "%s '%s': %s", ctx->option, path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return opt_fail(err, "%s '%s': not a regular file", ctx->option, path);
    if (tr_grow((void **)&l->includes, &l->cap_includes, l->nincludes + 1, sizeof *l->includes))
        return opt_fail(err, "out of memory");
    l->includes[l->nincludes++] = path;
    return true;
}

/* KIND key=value ...: see the man page. */
bool opt_set_light(options *o, const char *v, const opt_ctx *ctx, opt_err *err)
{
    static const char *const kinds[] = {"point", "parallel", "spot", "area"};
    look_light L;
    memset(&L, 0, sizeof L);
    L.color[0] = L.color[1] = L.color[2] = 1;
    L.radius = 30;
    L.falloff = 45;
    L.size[0] = L.size[1] = 1;
    L.samples[0] = L.samples[1] = 5;
    const char *p = v;
    while (*p == ' ')
        p++;
    size_t kl = strcspn(p, " ");
    int kind = -1;
    for (int k = 0; k < 4; k++)
        if (strlen(kinds[k]) == kl && strncmp(p, kinds[k], kl) == 0)
            kind = k;
    if (kind < 0)
        return opt_fail(err, "%s '%s': expected point, parallel, spot or area first", ctx->option,
                        v);
    L.kind = (look_light_kind)kind;
    p += kl;
    bool has_at = false;
    while (*p) {
        while (*p == ' ')
            p++;
        if (!*p)
            break;
        const char *key = p, *e;
        size_t n = strcspn(p, "= ");
        p += n;
        if (*p != '=')
            return opt_fail(err, "%s '%s': expected key=value at '%.*s'", ctx->option, v,
                            (int)n, key);
        p++;
        bool ok;
        double d[2];
#define KEY(s) (n == strlen(s) && strncmp(key, s, n) == 0)
        if (KEY("at"))
            ok = parse_vec(p, L.at, 3, &e), has_at = true;
        else if (KEY("to"))
            ok = parse_vec(p, L.to, 3, &e);
        else if (KEY("color") || KEY("colour"))
            ok = parse_vec(p, L.color, 3, &e) && L.color[0] >= 0 && L.color[1] >= 0 &&
                 L.color[2] >= 0;
        else if (KEY("radius") && L.kind == LOOK_LIGHT_SPOT)
            ok = parse_num(p, &e, &L.radius) && L.radius >= 0 && L.radius <= 90;
        else if (KEY("falloff") && L.kind == LOOK_LIGHT_SPOT)
            ok = parse_num(p, &e, &L.falloff) && L.falloff >= 0 && L.falloff <= 90;
        else if (KEY("size") && L.kind == LOOK_LIGHT_AREA)
            ok = parse_vec(p, L.size, 2, &e) && L.size[0] > 0 && L.size[1] > 0;
        else if (KEY("samples") && L.kind == LOOK_LIGHT_AREA) {
            ok = parse_vec(p, d, 2, &e) && d[0] >= 1 && d[0] <= 64 && d[1] >= 1 && d[1] <= 64 &&
                 d[0] == floor(d[0]) && d[1] == floor(d[1]);
            if (ok) {
                L.samples[0] = (int)d[0];
                L.samples[1] = (int)d[1];
            }
        } else
            return opt_fail(err, "%s '%s': no key '%.*s' for a %s light", ctx->option, v,
                            (int)n, key, kinds[kind]);
#undef KEY
        if (!ok || (*e && *e != ' '))
            return opt_fail(err, "%s '%s': bad value for '%.*s'", ctx->option, v, (int)n, key);
        p = e;
    }
    if (!has_at)
        return opt_fail(err, "%s '%s': the light needs at=X,Y,Z", ctx->option, v);
    if (L.kind == LOOK_LIGHT_SPOT && L.falloff < L.radius)
        return opt_fail(err, "%s '%s': falloff must not be less than radius", ctx->option, v);
    look_settings *l = &o->look;
    if (tr_grow((void **)&l->lights, &l->cap_lights, l->nlights + 1, sizeof L) != 0)
        return opt_fail(err, "out of memory");
    l->lights[l->nlights++] = L;
    return true;
}

/* ---- Applying -------------------------------------------------------------------------- */

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

const char *look_apply(const look_settings *l, scene *s)
{
    apply_size(l, s);
    mat4 view, inv;
    bool world = override_view(l, s, &view, &inv);
    if (look_overrides_camera(l))
        apply_camera(l, s, world, &view, &inv);
    if (l->no_gl_lights)
        s->nlights = 0;
    if (!look_overrides_camera(l) && l->nlights == 0)
        return NULL;
    if (world)
        return "camera and light overrides are in world coordinates (the frame's gluLookAt)";
    if (s->camera.kind == SCENE_CAMERA_LOOKAT)
        return NULL;
    return "camera and light overrides are in eye coordinates (no gluLookAt in the frame)";
}

/* ---- Writing --------------------------------------------------------------------------- */

static void put_vec(outbuf *ob, const double v[3])
{
    outbuf_putc(ob, '<');
    for (int k = 0; k < 3; k++) {
        if (k)
            outbuf_putc(ob, ',');
        outbuf_f32(ob, isfinite(v[k]) ? (float)v[k] : 0.0f);
    }
    outbuf_putc(ob, '>');
}

static void write_light(outbuf *ob, const look_light *L, bool world, const mat4 *view)
{
    double at[3], to[3];
    if (world) {
        xform(view, L->at, 1, at);
        xform(view, L->to, 1, to);
    } else {
        memcpy(at, L->at, sizeof at);
        memcpy(to, L->to, sizeof to);
    }
    outbuf_puts(ob, "light_source{");
    put_vec(ob, at);
    outbuf_puts(ob, " rgb");
    put_vec(ob, L->color);
    switch (L->kind) {
    case LOOK_LIGHT_POINT:
        break;
    case LOOK_LIGHT_PARALLEL:
        outbuf_puts(ob, " parallel point_at");
        put_vec(ob, to);
        break;
    case LOOK_LIGHT_SPOT:
        outbuf_puts(ob, " spotlight point_at");
        put_vec(ob, to);
        outbuf_puts(ob, " radius ");
        outbuf_f32(ob, (float)L->radius);
        outbuf_puts(ob, " falloff ");
        outbuf_f32(ob, (float)L->falloff);
        break;
    case LOOK_LIGHT_AREA: {
        /* Two axes across the direction to `to`, sized in the override's
         * space; the light faces its target. */
        double f[3] = {L->to[0] - L->at[0], L->to[1] - L->at[1], L->to[2] - L->at[2]};
        double a[3], b[3], up[3] = {0, 1, 0};
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
        double ae[3], be[3];
        if (world) {
            xform(view, a, 0, ae);
            xform(view, b, 0, be);
        } else {
            memcpy(ae, a, sizeof ae);
            memcpy(be, b, sizeof be);
        }
        outbuf_puts(ob, " area_light ");
        put_vec(ob, ae);
        outbuf_putc(ob, ',');
        put_vec(ob, be);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)L->samples[0]);
        outbuf_putc(ob, ',');
        outbuf_u64(ob, (uint64_t)L->samples[1]);
        outbuf_puts(ob, " adaptive 1 jitter circular orient");
        break;
    }
    }
    outbuf_puts(ob, "}\n");
}

int look_write_scene(outbuf *ob, const look_settings *l, const scene *s,
                     const char *const *include_names, size_t ninclude)
{
    if (l->radiosity)
        outbuf_puts(ob, "// --radiosity\nglobal_settings{radiosity{}}\n");
    if (l->nlights) {
        mat4 view, inv;
        bool world = override_view(l, s, &view, &inv);
        outbuf_puts(ob, world ? "// --light, given in world coordinates\n"
                              : "// --light, given in eye coordinates\n");
        for (size_t i = 0; i < l->nlights; i++)
            write_light(ob, &l->lights[i], world, &view);
    }
    if (ninclude) {
        /* World -> eye for the user's SDL: the scene is in eye coordinates. */
        mat4 view, inv;
        bool world = override_view(l, s, &view, &inv);
        outbuf_puts(ob, "// --include: RayGL_World takes world coordinates (after the frame's\n"
                        "// gluLookAt) to the scene's eye coordinates; identity without one.\n"
                        "#declare RayGL_World = transform{matrix<");
        for (int c = 0; c < 4; c++)
            for (int r = 0; r < 3; r++) {
                double m = world ? view.m[c * 4 + r] : (c == r ? 1 : 0);
                outbuf_f32(ob, isfinite(m) ? (float)m : 0.0f);
                if (c * 3 + r < 11)
                    outbuf_putc(ob, ',');
            }
        outbuf_puts(ob, ">}\n");
    }
    if (ninclude)
        /* POV-Ray's own default finish again (its manual's ambient 0.1,
         * diffuse 0.6, no emission): the scene's unlit default (povwrite.c)
         * is RayGL's, and would make the user's objects flat and unlit. */
        outbuf_puts(ob, "#default{finish{ambient 0.1 diffuse 0.6 emission 0}}\n");
    for (size_t i = 0; i < ninclude; i++) {
        /* Names are [A-Za-z0-9._-] (look_copy_includes): nothing to escape. */
        outbuf_puts(ob, "#include \"");
        outbuf_puts(ob, include_names[i]);
        outbuf_puts(ob, "\"\n");
    }
    return ob->failed ? -1 : 0;
}

int look_write_ini(outbuf *ob, const look_settings *l)
{
    if (l->antialias)
        outbuf_puts(ob, "; --antialias\nAntialias=On\nAntialias_Threshold=0.3\n");
    if (l->quality) {
        outbuf_puts(ob, "; --quality\nQuality=");
        outbuf_u64(ob, l->quality < 0 ? 0 : (uint64_t)l->quality);
        outbuf_putc(ob, '\n');
    }
    return ob->failed ? -1 : 0;
}

/* ---- Include files --------------------------------------------------------------------- */

void look_free_names(char **names, size_t n)
{
    for (size_t i = 0; names && i < n; i++)
        tr_free(names[i]);
    tr_free(names);
}

bool files_same(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fa ? fopen(b, "rb") : NULL;
    bool same = fa && fb;
    char ba[65536], bb[65536];
    while (same) {
        size_t na = fread(ba, 1, sizeof ba, fa), nb = fread(bb, 1, sizeof bb, fb);
        same = na == nb && memcmp(ba, bb, na) == 0 && !ferror(fa) && !ferror(fb);
        if (na == 0)
            break;
    }
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return same;
}

/* An unchanged copy keeps its time: rendered frames stay up to date. */
static int copy_file(const char *from, const char *to, char *msg, size_t cap)
{
    if (files_same(from, to))
        return 0;
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.%ld.tmp", to, (long)getpid());
    int in = open(from, O_RDONLY | O_CLOEXEC);
    if (in < 0) {
        snprintf(msg, cap, "%s: cannot read: %s", from, strerror(errno));
        return -1;
    }
    int out = open(tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (out < 0) {
        snprintf(msg, cap, "%s: cannot create: %s", tmp, strerror(errno));
        close(in);
        return -1;
    }
    char buf[65536];
    ssize_t n;
    int rc = 0, e = 0;
    while ((n = read(in, buf, sizeof buf)) != 0) {
        if (n < 0) {
            if (errno == EINTR)
                continue;
            rc = -1, e = errno;
            break;
        }
        for (ssize_t off = 0; off < n;) {
            ssize_t w = write(out, buf + off, (size_t)(n - off));
            if (w < 0 && errno == EINTR)
                continue;
            if (w < 0) {
                rc = -1, e = errno;
                break;
            }
            off += w;
        }
        if (rc)
            break;
    }
    close(in);
    if (close(out) != 0 && rc == 0)
        rc = -1, e = errno;
    if (rc == 0 && rename(tmp, to) != 0)
        rc = -1, e = errno;
    if (rc != 0) {
        unlink(tmp);
        snprintf(msg, cap, "%s: cannot copy to %s: %s", from, to, strerror(e));
    }
    return rc;
}

int look_copy_includes(const look_settings *l, const char *dir, char ***names, char *msg,
                       size_t cap)
{
    *names = NULL;
    if (!l->nincludes)
        return 0;
    char **v = tr_realloc(NULL, l->nincludes * sizeof *v);
    if (!v) {
        snprintf(msg, cap, "out of memory");
        return -1;
    }
    memset(v, 0, l->nincludes * sizeof *v);
    for (size_t i = 0; i < l->nincludes; i++) {
        const char *base = strrchr(l->includes[i], '/');
        base = base ? base + 1 : l->includes[i];
        char name[160];
        int n = snprintf(name, sizeof name, "include-%zu-", i + 1);
        for (const char *p = base; *p && n + 1 < (int)sizeof name; p++) {
            char c = *p;
            bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                      (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
            name[n++] = ok ? c : '_';
        }
        name[n] = '\0';
        size_t dl = strlen(dir);
        char *path = tr_realloc(NULL, dl + strlen(name) + 2);
        v[i] = tr_realloc(NULL, strlen(name) + 1);
        if (!path || !v[i]) {
            tr_free(path);
            look_free_names(v, l->nincludes);
            snprintf(msg, cap, "out of memory");
            return -1;
        }
        strcpy(v[i], name);
        sprintf(path, "%s%s%s", dir, dl && dir[dl - 1] == '/' ? "" : "/", name);
        int rc = copy_file(l->includes[i], path, msg, cap);
        tr_free(path);
        if (rc != 0) {
            look_free_names(v, l->nincludes);
            return -1;
        }
    }
    *names = v;
    return 0;
}

int look_add_lights(const look_settings *l, scene *s)
{
    mat4 view, inv;
    bool world = override_view(l, s, &view, &inv);
    for (size_t i = 0; i < l->nlights; i++) {
        const look_light *L = &l->lights[i];
        scene_light *sl = scene_add_light(s);
        if (!sl)
            return -1;
        memset(sl, 0, sizeof *sl);
        double at[3], to[3];
        if (world) {
            xform(&view, L->at, 1, at);
            xform(&view, L->to, 1, to);
        } else {
            memcpy(at, L->at, sizeof at);
            memcpy(to, L->to, sizeof to);
        }
        /* An area light as a point at its centre: a writer without area
         * lights keeps its brightness and place. */
        sl->kind = L->kind == LOOK_LIGHT_PARALLEL ? SCENE_LIGHT_PARALLEL
                   : L->kind == LOOK_LIGHT_SPOT   ? SCENE_LIGHT_SPOT
                                                  : SCENE_LIGHT_POINT;
        sl->aimed = true; /* lights everything, as POV-Ray's added lights do */
        for (int k = 0; k < 3; k++) {
            sl->position[k] = at[k];
            sl->point_at[k] = to[k];
            sl->direction[k] = to[k] - at[k];
            sl->color[k] = (float)L->color[k];
        }
        sl->spot_cutoff = (float)(L->kind == LOOK_LIGHT_SPOT ? L->falloff : 180);
        /* POV-Ray's full-intensity radius as GL's exponent whose falloff is
         * half way down midway between radius and falloff */
        double mid = (L->radius + L->falloff) / 2 * 3.14159265358979323846 / 180;
        if (L->kind == LOOK_LIGHT_SPOT && L->radius < L->falloff && mid > 0 && cos(mid) > 0)
            sl->spot_exponent = (float)(log(0.5) / log(cos(mid)));
        sl->attenuation[0] = 1; /* POV-Ray's lights do not fade */
    }
    return 0;
}
