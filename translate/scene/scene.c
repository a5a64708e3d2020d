/* scene.c: the scene model's storage and its cameras (scene.h).
 *
 * The camera formulas generalise docs/mapping.md section "Camera": a GL
 * projection maps eye point p to NDC x = r0.p / r3.p, y = r1.p / r3.p (ri
 * the matrix rows, p homogeneous). When r3 has a spatial part the
 * projection has a centre C (rows 0, 1, 3 vanish there) and the ray
 * through NDC (x, y) is C + t B^-1 (x, y, 1), B the spatial 3x3 of rows 0,
 * 1, 3: a POV-Ray perspective camera with direction B^-1 e3 and right, up
 * twice B^-1 e1, B^-1 e2. For glFrustum this is direction <p8/p0, p9/p5,
 * -1>, right <2/p0,0,0>, up <0,2/p5,0>, the reference's formula. When r3 is
 * (0,0,0,w) the projection is parallel: orthographic.
 */
#include "scene.h"

#include <math.h>
#include <string.h>

#include "talloc.h"

void scene_init(scene *s)
{
    memset(s, 0, sizeof *s);
    int vp[4] = {0, 0, 640, 480};
    mat4 id = mat4_identity();
    scene_camera_from_gl(&s->camera, &id, vp);
}

void scene_finish(scene *s)
{
    tr_free(s->verts);
    tr_free(s->tris);
    tr_free(s->meshes);
    tr_free(s->lines);
    tr_free(s->points);
    tr_free(s->lights);
    tr_free(s->solids);
    for (size_t i = 0; i < s->ntextures; i++)
        tr_free(s->textures[i].rgba);
    tr_free(s->textures);
    tr_free(s->protos);
    tr_free(s->instances);
    tr_free(s->materials);
    tr_free(s->overlay);
    tr_free(s->names);
    tr_free(s->clips);
    tr_free(s->pstipples);
    tr_free(s->stencil_tris);
    memset(s, 0, sizeof *s);
}

void scene_reset(scene *s)
{
    scene_clear_geometry(s);
    s->nlights = 0;
    s->nmaterials = 0;
    s->nnames = s->names_last = 0;
    s->nclips = s->clips_last = 0;
    s->npstipples = 0;
    s->nstencil = 0;
    s->lights_fixed = false;
    s->nlightsets = 0;
    memset(&s->fog, 0, sizeof s->fog);
    s->have_camera = false;
    s->have_view = false;
    memset(&s->options, 0, sizeof s->options);
    s->antialias_depth = 0;
    s->focal_blur = false;
    s->failed = false;
    memset(s->background, 0, sizeof s->background);
    int vp[4] = {0, 0, 640, 480};
    mat4 id = mat4_identity();
    scene_camera_from_gl(&s->camera, &id, vp);
}

void scene_clear_geometry(scene *s)
{
    s->nverts = s->ntris = s->nmeshes = s->nlines = s->npoints = s->nsolids = 0;
    for (size_t i = 0; i < s->ntextures; i++)
        tr_free(s->textures[i].rgba);
    s->ntextures = 0;
    s->nprotos = s->ninstances = s->mesh_floor = 0;
    tr_free(s->overlay); /* a glClear erases the pixels drawn too */
    s->overlay = NULL;
    s->overlay_w = s->overlay_h = 0;
    s->generation++;
}

void scene_mark_take(const scene *s, scene_mark *m)
{
    *m = (scene_mark){s->nverts,  s->ntris,     s->nmeshes,   s->nlines,     s->npoints,
                      s->nsolids, s->ntextures, s->nprotos,   s->ninstances, s->nmaterials};
}

void scene_truncate(scene *s, const scene_mark *m)
{
#define CUT(f) if (s->f > m->f) s->f = m->f
    CUT(nverts);
    CUT(ntris);
    CUT(nmeshes);
    CUT(nlines);
    CUT(npoints);
    CUT(nsolids);
    CUT(nprotos);
    CUT(ninstances);
    CUT(nmaterials);
#undef CUT
    for (size_t i = m->ntextures; i < s->ntextures; i++)
        tr_free(s->textures[i].rgba);
    if (s->ntextures > m->ntextures)
        s->ntextures = m->ntextures;
    s->mesh_floor = s->nmeshes; /* the kept pass's last mesh takes no more triangles */
    s->generation++;
}

/* Grows a pool for one more item, within SCENE_MAX_ITEMS. */
static void *add_item(scene *s, void **pool, size_t *n, size_t *cap, size_t elem)
{
    if (s->failed)
        return NULL;
    if (*n >= SCENE_MAX_ITEMS || tr_grow(pool, cap, *n + 1, elem) != 0) {
        s->failed = true;
        return NULL;
    }
    void *p = (char *)*pool + *n * elem;
    (*n)++;
    memset(p, 0, elem);
    return p;
}

scene_vertex *scene_reserve_vertices(scene *s, size_t n)
{
    if (s->failed)
        return NULL;
    if (n > SCENE_MAX_VERTICES - s->nverts ||
        tr_grow((void **)&s->verts, &s->cap_verts, s->nverts + n, sizeof *s->verts) != 0) {
        s->failed = true;
        return NULL;
    }
    return s->verts + s->nverts;
}

bool scene_look_equal(const scene_look *a, const scene_look *b)
{
    return memcmp(a, b, sizeof *a) == 0;
}

scene_mesh *scene_mesh_for(scene *s, const mat4 *to_eye, bool in_eye, const scene_look *look)
{
    if (s->nmeshes > s->mesh_floor) {
        scene_mesh *m = &s->meshes[s->nmeshes - 1];
        if (m->in_eye == in_eye && scene_look_equal(&m->look, look) &&
            mat4_equal_f32(&m->to_eye, to_eye))
            return m;
        if (m->tri_count == 0) { /* an empty run: reuse it */
            m->to_eye = *to_eye;
            m->in_eye = in_eye;
            m->look = *look;
            return m;
        }
    }
    scene_mesh *m = add_item(s, (void **)&s->meshes, &s->nmeshes, &s->cap_meshes, sizeof *m);
    if (!m)
        return NULL;
    m->to_eye = *to_eye;
    m->in_eye = in_eye;
    m->look = *look;
    m->first_tri = s->ntris;
    m->tri_count = 0;
    return m;
}

bool scene_add_tri_grow(scene *s, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking)
{
    if (s->failed || s->nmeshes == 0)
        return false;
    if (s->ntris >= SCENE_MAX_ITEMS ||
        tr_grow((void **)&s->tris, &s->cap_tris, s->ntris + 1, sizeof *s->tris) != 0) {
        s->failed = true;
        return false;
    }
    return scene_add_tri(s, a, b, c, provoking); /* room now: the inline path */
}

scene_line *scene_add_line(scene *s)
{
    return add_item(s, (void **)&s->lines, &s->nlines, &s->cap_lines, sizeof(scene_line));
}

scene_proto *scene_add_proto(scene *s)
{
    return add_item(s, (void **)&s->protos, &s->nprotos, &s->cap_protos, sizeof(scene_proto));
}

scene_instance *scene_add_instance(scene *s)
{
    return add_item(s, (void **)&s->instances, &s->ninstances, &s->cap_instances,
                    sizeof(scene_instance));
}

scene_point *scene_add_point(scene *s)
{
    return add_item(s, (void **)&s->points, &s->npoints, &s->cap_points, sizeof(scene_point));
}

scene_light *scene_add_light(scene *s)
{
    return add_item(s, (void **)&s->lights, &s->nlights, &s->cap_lights, sizeof(scene_light));
}

scene_solid *scene_add_solid(scene *s)
{
    return add_item(s, (void **)&s->solids, &s->nsolids, &s->cap_solids, sizeof(scene_solid));
}

bool scene_texture_sampling_same(const scene_texture *a, const scene_texture *b)
{
    return a->width == b->width && a->height == b->height &&
           a->repeat_s == b->repeat_s && a->repeat_t == b->repeat_t && a->linear == b->linear &&
           a->border_s == b->border_s && a->border_t == b->border_t &&
           a->to_border_s == b->to_border_s && a->to_border_t == b->to_border_t &&
           memcmp(a->border, b->border, sizeof a->border) == 0 &&
           a->env_mode == b->env_mode && a->colour_is_texel == b->colour_is_texel &&
           memcmp(a->env_color, b->env_color, sizeof a->env_color) == 0 &&
           a->mirror_s == b->mirror_s && a->mirror_t == b->mirror_t &&
           a->alpha_func == b->alpha_func && a->alpha_ref == b->alpha_ref &&
           a->alpha_af == b->alpha_af && a->alpha_uses_af == b->alpha_uses_af &&
           a->mip_next == b->mip_next && a->mip_filter == b->mip_filter &&
           a->min_lod == b->min_lod && a->max_lod == b->max_lod && a->cube == b->cube &&
           a->lod_bias == b->lod_bias;
}

static bool texture_same(const scene_texture *a, const scene_texture *b)
{
    return a->hash == b->hash && scene_texture_sampling_same(a, b) &&
           memcmp(a->rgba, b->rgba, (size_t)a->width * (size_t)a->height * 4) == 0;
}

/* FNV-1a of the size and texels. */
static uint64_t texels_hash(const scene_texture *t)
{
    uint64_t h = 0xcbf29ce484222325ull;
    uint32_t dims[2] = {(uint32_t)t->width, (uint32_t)t->height};
    const uint8_t *d = (const uint8_t *)dims;
    for (size_t i = 0; i < sizeof dims; i++)
        h = (h ^ d[i]) * 0x100000001b3ull;
    size_t n = (size_t)t->width * (size_t)t->height * 4;
    for (size_t i = 0; i < n; i++)
        h = (h ^ t->rgba[i]) * 0x100000001b3ull;
    return h;
}

int32_t scene_add_texture(scene *s, const scene_texture *in)
{
    scene_texture tt = *in, *t = &tt;
    t->hash = texels_hash(t);
    for (size_t i = s->ntextures; i-- > 0;)
        if (texture_same(&s->textures[i], t)) {
            tr_free(t->rgba);
            return (int32_t)i;
        }
    if (s->ntextures >= INT32_MAX) {
        tr_free(t->rgba);
        s->failed = true;
        return -1;
    }
    scene_texture *n = add_item(s, (void **)&s->textures, &s->ntextures, &s->cap_textures,
                                sizeof *n);
    if (!n) {
        tr_free(t->rgba);
        return -1;
    }
    *n = *t;
    return (int32_t)(s->ntextures - 1);
}

int32_t scene_material_index(scene *s, const scene_material *m)
{
    /* Newest first: a frame switches among a few materials. */
    for (size_t i = s->nmaterials; i-- > 0;)
        if (memcmp(&s->materials[i], m, sizeof *m) == 0)
            return (int32_t)i;
    if (s->nmaterials >= INT32_MAX)
        return -1;
    scene_material *n = add_item(s, (void **)&s->materials, &s->nmaterials, &s->cap_materials,
                                 sizeof *n);
    if (!n)
        return -1;
    memcpy(n, m, sizeof *n);
    return (int32_t)(s->nmaterials - 1);
}

uint32_t scene_names_index(scene *s, const uint32_t *names, uint32_t n)
{
    if (n == 0 || s->failed)
        return 0;
    if (s->names_last) {
        const uint32_t *l = s->names + s->names_last;
        if (l[-1] == n && memcmp(l, names, n * sizeof *names) == 0)
            return (uint32_t)s->names_last;
    }
    if (s->nnames + n + 1 > s->cap_names) {
        size_t cap = s->cap_names ? 2 * s->cap_names : 256;
        while (cap < s->nnames + n + 1)
            cap *= 2;
        uint32_t *p = cap <= UINT32_MAX / 2 ? tr_realloc(s->names, cap * sizeof *p) : NULL;
        if (!p) {
            s->failed = true;
            return 0;
        }
        s->names = p;
        s->cap_names = cap;
    }
    s->names[s->nnames] = n;
    memcpy(s->names + s->nnames + 1, names, n * sizeof *names);
    s->names_last = s->nnames + 1;
    s->nnames += n + 1;
    return (uint32_t)s->names_last;
}

const uint32_t *scene_names(const scene *s, uint32_t id, uint32_t *n)
{
    *n = 0;
    if (id == 0 || id > s->nnames || s->names[id - 1] > s->nnames - id)
        return NULL;
    *n = s->names[id - 1];
    return s->names + id;
}

/* ---- Cameras ---------------------------------------------------------------- */

/* Solves the 3x3 system with rows a[0..2] for x: a x = b (Cramer). */
static bool solve3(double a[3][3], const double b[3], double x[3])
{
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                 a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if (det == 0 || !isfinite(det))
        return false;
    for (int k = 0; k < 3; k++) {
        double m[3][3];
        memcpy(m, a, sizeof m);
        for (int r = 0; r < 3; r++)
            m[r][k] = b[r];
        x[k] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
               det;
        if (!isfinite(x[k]))
            return false;
    }
    return true;
}

static void set_size(scene_camera *cam, const int viewport[4])
{
    cam->width = viewport[2] > 0 ? viewport[2] : 1;
    cam->height = viewport[3] > 0 ? viewport[3] : 1;
}

/* Near and far planes: -w <= z_clip <= w, i.e. (r3 + r2).p >= 0 and
 * (r3 - r2).p >= 0, normalised on their spatial part. */
static void set_clip(scene_camera *cam, double r[4][4])
{
    cam->has_clip = true;
    for (int i = 0; i < 2; i++) {
        double s = i == 0 ? 1 : -1, len = 0;
        for (int k = 0; k < 4; k++)
            cam->clip[i][k] = r[3][k] + s * r[2][k];
        len = sqrt(dot3(cam->clip[i], cam->clip[i]));
        if (!(len > 0) || !isfinite(len)) {
            cam->has_clip = false;
            return;
        }
        for (int k = 0; k < 4; k++)
            cam->clip[i][k] /= len;
    }
}

static bool camera_from_rows(scene_camera *cam, double r[4][4])
{
    static const double e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0}, e3[3] = {0, 0, 1};

    if (r[3][0] == 0 && r[3][1] == 0 && r[3][2] == 0) {
        /* Parallel projection: scale the rows so that w = 1. */
        double w = r[3][3];
        if (w == 0 || !isfinite(w))
            return false;
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 4; k++)
                r[i][k] /= w;
        double a[3][3] = {{r[0][0], r[0][1], r[0][2]},
                          {r[1][0], r[1][1], r[1][2]},
                          {r[2][0], r[2][1], r[2][2]}};
        double rhs[3] = {-r[0][3], -r[1][3], -1 - r[2][3]}; /* centre of the near plane */
        double d[3];
        if (!solve3(a, rhs, cam->location))
            return false;
        cross3(a[0], a[1], d);
        double len = sqrt(dot3(d, d));
        if (!(len > 0) || !isfinite(len))
            return false;
        if (dot3(a[2], d) < 0) /* look toward increasing depth */
            len = -len;
        for (int k = 0; k < 3; k++)
            cam->direction[k] = d[k] / len;
        double b[3][3] = {{a[0][0], a[0][1], a[0][2]},
                          {a[1][0], a[1][1], a[1][2]},
                          {cam->direction[0], cam->direction[1], cam->direction[2]}};
        double two_e1[3] = {2, 0, 0}, two_e2[3] = {0, 2, 0};
        if (!solve3(b, two_e1, cam->right) || !solve3(b, two_e2, cam->up))
            return false;
        cam->kind = SCENE_CAMERA_ORTHOGRAPHIC;
        set_clip(cam, r);
        return true;
    }

    double b[3][3] = {{r[0][0], r[0][1], r[0][2]},
                      {r[1][0], r[1][1], r[1][2]},
                      {r[3][0], r[3][1], r[3][2]}};
    double rhs[3] = {-r[0][3], -r[1][3], -r[3][3]};
    if (!solve3(b, rhs, cam->location) || !solve3(b, e3, cam->direction) ||
        !solve3(b, e1, cam->right) || !solve3(b, e2, cam->up))
        return false;
    for (int k = 0; k < 3; k++) {
        cam->right[k] *= 2;
        cam->up[k] *= 2;
    }
    cam->kind = SCENE_CAMERA_PERSPECTIVE;
    set_clip(cam, r);
    return true;
}

bool scene_camera_from_gl(scene_camera *cam, const mat4 *proj, const int viewport[4])
{
    double r[4][4];
    memset(cam, 0, sizeof *cam);
    set_size(cam, viewport);
    if (mat4_finite(proj)) {
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 4; k++)
                r[i][k] = proj->m[k * 4 + i];
        if (camera_from_rows(cam, r))
            return true;
    }
    /* The identity projection's camera: orthographic, [-1, 1]^3. */
    memset(r, 0, sizeof r);
    for (int i = 0; i < 4; i++)
        r[i][i] = 1;
    int w = cam->width, h = cam->height;
    memset(cam, 0, sizeof *cam);
    camera_from_rows(cam, r);
    cam->width = w;
    cam->height = h;
    return false;
}

bool scene_camera_lookat(scene_camera *cam, const double loc[3], const double look[3],
                         double fovy_deg, int width, int height)
{
    static const double sky[3] = {0, 1, 0};
    double d[3] = {look[0] - loc[0], look[1] - loc[1], look[2] - loc[2]}, rt[3], up[3];
    bool ok = true;

    memset(cam, 0, sizeof *cam);
    cam->kind = SCENE_CAMERA_LOOKAT;
    cam->width = width > 0 ? width : 1;
    cam->height = height > 0 ? height : 1;
    for (int k = 0; k < 3; k++) {
        cam->location[k] = isfinite(loc[k]) ? loc[k] : 0;
        cam->look_at[k] = isfinite(look[k]) ? look[k] : 0;
    }
    double len = sqrt(dot3(d, d));
    if (!(len > 0) || !isfinite(len)) {
        d[0] = d[1] = 0;
        d[2] = -1;
        len = 1;
        ok = false;
    }
    for (int k = 0; k < 3; k++)
        d[k] /= len;
    cross3(d, sky, rt); /* right = forward x sky: +x when looking down -z */
    double rl = sqrt(dot3(rt, rt));
    if (!(rl > 1e-9)) {
        rt[0] = 1;
        rt[1] = rt[2] = 0;
        rl = 1;
        ok = false;
    }
    for (int k = 0; k < 3; k++)
        rt[k] /= rl;
    cross3(rt, d, up);
    if (!(fovy_deg > 0 && fovy_deg < 180))
        fovy_deg = 2 * atan(0.5) * 180 / 3.14159265358979323846; /* POV-Ray's default */
    double dl = 0.5 / tan(fovy_deg * 3.14159265358979323846 / 360);
    double aspect = (double)cam->width / (double)cam->height;
    for (int k = 0; k < 3; k++) {
        cam->direction[k] = d[k] * dl;
        cam->right[k] = rt[k] * aspect;
        cam->up[k] = up[k];
    }
    return ok;
}

bool scene_camera_coords(const scene_camera *cam, const double p[3], double x[3])
{
    double a[3][3], rel[3];
    for (int k = 0; k < 3; k++) {
        a[k][0] = cam->direction[k];
        a[k][1] = cam->right[k];
        a[k][2] = cam->up[k];
        rel[k] = p[k] - cam->location[k];
    }
    return solve3(a, rel, x) && isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]);
}

bool scene_camera_project(const scene_camera *cam, const double p[3], double out[2])
{
    double x[3];
    if (!scene_camera_coords(cam, p, x))
        return false;
    double t = 1;
    if (cam->kind != SCENE_CAMERA_ORTHOGRAPHIC) {
        if (!(x[0] > 0))
            return false;
        t = x[0];
    }
    out[0] = x[1] / t * cam->width;
    out[1] = x[2] / t * cam->height;
    return isfinite(out[0]) && isfinite(out[1]);
}

bool scene_camera_pixel_size(const scene_camera *cam, const double p[3], double *px, double *py)
{
    double rl = sqrt(dot3(cam->right, cam->right)), ul = sqrt(dot3(cam->up, cam->up));
    double t = 1, x[3];
    if (cam->kind != SCENE_CAMERA_ORTHOGRAPHIC) {
        /* The image spans t right by t up at that depth. */
        if (!scene_camera_coords(cam, p, x) || !(x[0] > 0))
            return false;
        t = x[0];
    }
    *px = t * rl / cam->width;
    *py = t * ul / cam->height;
    return isfinite(*px) && isfinite(*py);
}

bool scene_lights_specular_ratio(const scene_light *l, size_t n, double *ratio)
{
    double dd = 0, ds = 0;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            dd += (double)l[i].color[k] * l[i].color[k];
            ds += (double)l[i].color[k] * l[i].specular[k];
        }
    double r = dd > 0 && isfinite(ds / dd) ? ds / dd : 0;
    *ratio = r;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            if (fabs(r * l[i].color[k] - l[i].specular[k]) > 1e-6 * (1 + fabs(l[i].specular[k])))
                return false;
    return true;
}

bool scene_lights_specular_channels(const scene_light *l, size_t n, double t[3])
{
    for (int k = 0; k < 3; k++) {
        t[k] = -1;
        for (size_t i = 0; i < n; i++) {
            double d = l[i].color[k], sp = l[i].specular[k];
            if (d == 0) {
                if (sp != 0)
                    return false;
                continue;
            }
            double r = sp / d;
            if (t[k] < 0)
                t[k] = r;
            else if (fabs(r - t[k]) > 1e-6 * (1 + t[k]))
                return false;
        }
        if (!(t[k] > 0) || !isfinite(t[k]))
            return false;
    }
    return true;
}

bool scene_needs_quality6(const scene *s)
{
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *m = &s->meshes[i];
        if (m->tri_count > 0 && (m->look.texture >= 0 || m->look.texture1 >= 0 ||
                                 m->look.blend == SCENE_BLEND_ALPHA))
            return true;
    }
    size_t n = s->overlay ? (size_t)s->overlay_w * (size_t)s->overlay_h : 0;
    for (size_t p = 0; p < n; p++)
        if (s->overlay[4 * p + 3] != 0 && s->overlay[4 * p + 3] != 255)
            return true;
    return false;
}
