/* gen_corpus.c: writes the fuzz seed corpus (tests/format/corpus/).
 *
 * Usage: gen-corpus DIR. Small traces that between them hold every row of
 * the table with random valid arguments, with and without an index, with
 * command and byte resources, plus bare command sequences. Deterministic:
 * the same binary writes the same files. The files are checked in; rerun
 * this only to refresh them (and review the diff). eval-*.bin hold evaluator
 * sequences with valid maps (random blobs rarely have a map's size), so the
 * fuzzers start from meshes that draw; pixels.bin holds bitmaps and pixel
 * rectangles with resources of their size; accum-passes.bin accumulated
 * passes; select-scissor.bin a picking pass, named draws and scissored
 * clears and draws; nurbs.bin GLU NURBS surfaces (trimmed, outlined) and
 * curves whose knots and points fit their sizes. The corpus also holds
 * recorded-*.bin, traces written by libraygl for the image tests (recorded-nurbs-trim.bin: nurbs_trim's).
 */
#include "testutil.h"

static uint8_t seq[1 << 16];

static size_t random_sequence(rng *r, size_t first_row, size_t rows, size_t *next_row)
{
    size_t nrows, len = 0;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&nrows);
    static rgl_cmd cmd;
    size_t i;
    for (i = first_row; i < nrows && i < first_row + rows; i++) {
        random_cmd(r, &cmd, all[i]->opcode);
        for (uint32_t k = 0; k < cmd.nargs; k++) {
            if (cmd.arg[k].kind == RGL_ARG_STRING || cmd.arg[k].kind == RGL_ARG_BLOB)
                cmd.arg[k].count = cmd.arg[k].count > 12 ? 12 : cmd.arg[k].count;
            if (cmd.arg[k].kind == RGL_ARG_COUNTED && cmd.arg[k].count > 4)
                cmd.arg[k].count = 4;
        }
        len += rgl_cmd_encode(&cmd, seq + len, sizeof seq - len);
    }
    if (next_row)
        *next_row = i;
    return len;
}

static int write_file(const char *dir, const char *name, const uint8_t *data, size_t size)
{
    char path[1024];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size) {
        fprintf(stderr, "gen-corpus: cannot write %s\n", path);
        if (f)
            fclose(f);
        return 1;
    }
    fclose(f);
    return 0;
}

static int write_trace(rng *r, const char *dir, const char *name, bool with_index,
                       size_t rows_per_frame)
{
    static const char info[] = "program=gen-corpus\nrecorder=raygl test\n";
    static const uint8_t texels[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
    rgl_trace_builder *b = rgl_trace_builder_create();
    const uint8_t *data;
    size_t size, nrows, row = 0, len;
    uint32_t snap = 0, tex = 0, frame = 0;
    int rc = 1;

    rgl_cmd_info_all(&nrows);
    if (!b)
        return 1;
    rgl_trace_builder_info(b, info, sizeof info - 1);
    len = random_sequence(r, 0, 6, NULL);
    rgl_trace_builder_resource(b, RGL_RES_COMMANDS, seq, len, &snap);
    rgl_trace_builder_resource(b, RGL_RES_BYTES, texels, sizeof texels, &tex);
    while (row < nrows) {
        len = random_sequence(r, row, rows_per_frame, &row);
        if (rgl_trace_builder_frame(b, frame % 2, frame, frame % 2 ? RGL_FRAME_STATE_CARRIED : 0,
                                    frame % 2 ? 0 : snap, seq, len) != RGL_OK)
            goto out;
        frame++;
    }
    if (rgl_trace_builder_finish(b, with_index, &data, &size) == RGL_OK)
        rc = write_file(dir, name, data, size);
out:
    rgl_trace_builder_destroy(b);
    return rc;
}

/* ---- Evaluators: maps whose blobs fit their orders ------------------------------- */

static size_t eval_len;

/* Appends command `op` with scalars v (in row order, skipping the blob) and,
 * for a map row, a blob of n little-endian floats (or doubles) from pts. */
static void eval_cmd(uint32_t op, const double *v, size_t nv, const double *pts, size_t n)
{
    static rgl_cmd cmd;
    static uint8_t blob[4096];
    if (rgl_cmd_init(&cmd, op) != RGL_OK)
        return;
    size_t used = 0;
    for (uint32_t k = 0; k < cmd.nargs; k++) {
        rgl_arg *a = &cmd.arg[k];
        if (a->kind == RGL_ARG_BLOB) {
            bool dbl = cmd.arg[1].type == RGL_T_d;
            for (size_t i = 0; i < n; i++) {
                if (dbl)
                    rgl_put_d(blob + 8 * i, pts[i]);
                else
                    rgl_put_f(blob + 4 * i, (float)pts[i]);
            }
            a->bytes = blob;
            a->count = (uint32_t)(n * (dbl ? 8 : 4));
        } else if (a->kind == RGL_ARG_COUNTED) { /* the rest of v */
            static double rest[16];
            a->count = 0;
            while (used < nv && a->count < 16)
                rest[a->count++] = v[used++];
            a->array = rest;
        } else if (a->kind == RGL_ARG_ARRAY) {
            static double arr[RGL_MAX_ARGS][4];
            for (uint32_t c = 0; c < a->count; c++)
                arr[k][c] = used < nv ? v[used++] : 0;
            a->array = arr[k];
        } else if (a->type == RGL_T_f || a->type == RGL_T_d) {
            a->v.f = used < nv ? v[used++] : 0;
        } else if (a->type == RGL_T_i) {
            a->v.i = used < nv ? (int64_t)v[used++] : 0;
        } else {
            a->v.u = used < nv ? (uint64_t)v[used++] : 0;
        }
    }
    eval_len += rgl_cmd_encode(&cmd, seq + eval_len, sizeof seq - eval_len);
}

#define EV(name, ...)                                                                   \
    eval_cmd(RGL_OP_##name, (const double[]){__VA_ARGS__},                              \
             sizeof((const double[]){__VA_ARGS__}) / sizeof(double), NULL, 0)

static int write_eval(const char *dir)
{
    double cubic[4 * 3], patch[4 * 4 * 3], col[2 * 2 * 4], tex[2 * 2 * 2], w4[3 * 4];
    for (int i = 0; i < 4; i++) {
        cubic[3 * i] = i;
        cubic[3 * i + 1] = (i % 3) * 0.5;
        cubic[3 * i + 2] = -1;
        for (int j = 0; j < 4; j++) {
            patch[12 * i + 3 * j] = i - 1.5;
            patch[12 * i + 3 * j + 1] = j - 1.5;
            patch[12 * i + 3 * j + 2] = (i * j) % 3 * 0.4;
        }
    }
    for (int i = 0; i < 16; i++)
        col[i] = (i % 5) * 0.25;
    for (int i = 0; i < 8; i++)
        tex[i] = (i % 3) * 0.5;
    for (int i = 0; i < 12; i++)
        w4[i] = i % 4 == 3 ? 1 + i / 4 : i * 0.3;
    int rc = 0;

    eval_len = 0;
    EV(Ortho, -3, 3, -3, 3, -5, 5);
    eval_cmd(RGL_OP_Map2f, (const double[]){0x0DB7, 0, 1, 12, 4, 0, 1, 3, 4}, 9, patch, 48);
    eval_cmd(RGL_OP_Map2d, (const double[]){0x0DB0, 0, 1, 8, 2, 0, 1, 4, 2}, 9, col, 16);
    eval_cmd(RGL_OP_Map2f, (const double[]){0x0DB4, 0, 1, 4, 2, 0, 1, 2, 2}, 9, tex, 8);
    EV(Enable, 0x0DB7);
    EV(Enable, 0x0DB0);
    EV(Enable, 0x0DB4);
    EV(Enable, 0x0D80); /* GL_AUTO_NORMAL */
    EV(Enable, 0x0B50); /* GL_LIGHTING */
    EV(MapGrid2f, 6, 0, 1, 5, 0, 1);
    EV(EvalMesh2, 0x1B02, 0, 6, 0, 5);
    EV(MapGrid2d, 3, 0.25, 0.75, 2, 0, 1);
    EV(EvalMesh2, 0x1B01, 0, 3, 0, 2);
    EV(EvalMesh2, 0x1B00, 1, 2, 0, 2);
    EV(Begin, 0x0008); /* GL_QUAD_STRIP */
    EV(EvalCoord2f, 0, 0);
    EV(EvalCoord2fv, 0, 1);
    EV(EvalCoord2d, 1, 0);
    EV(EvalCoord2dv, 1, 1);
    EV(EvalPoint2, 1, 1);
    EV(EvalPoint2, 2, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    rc |= write_file(dir, "eval-map2.bin", seq, eval_len);

    eval_len = 0;
    EV(Ortho, -3, 3, -3, 3, -5, 5);
    eval_cmd(RGL_OP_Map1f, (const double[]){0x0D97, 2, 4, 3, 4}, 5, cubic, 12);
    eval_cmd(RGL_OP_Map1d, (const double[]){0x0D98, -1, 1, 4, 3}, 5, w4, 12);
    eval_cmd(RGL_OP_Map1f, (const double[]){0x0D90, 0, 1, 4, 2}, 5, col, 8);
    EV(Enable, 0x0D97);
    EV(Enable, 0x0D90);
    EV(Enable, 0x0D91); /* GL_MAP1_INDEX: noted, not drawn */
    EV(MapGrid1f, 8, 2, 4);
    EV(EvalMesh1, 0x1B01, 0, 8);
    EV(Enable, 0x0D98);
    EV(MapGrid1d, 4, -1, 1);
    EV(EvalMesh1, 0x1B00, 0, 4);
    EV(Begin, 0x0003); /* GL_LINE_STRIP */
    EV(EvalCoord1f, 2);
    EV(EvalCoord1fv, 3);
    EV(EvalCoord1d, 3.5);
    EV(EvalCoord1dv, 4);
    EV(EvalPoint1, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    rc |= write_file(dir, "eval-map1.bin", seq, eval_len);
    return rc;
}

/* ---- Pixels: bitmaps and pixel rectangles with resources of their size ---------- */

static int write_pixels(const char *dir)
{
    static const uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
    static const uint8_t bits[2] = {0xa5, 0x5a};
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint32_t px = 0, bm = 0;
    const uint8_t *data;
    size_t size;
    int rc = 1;
    if (!b)
        return 1;
    rgl_trace_builder_resource(b, RGL_RES_BYTES, rgba, sizeof rgba, &px);
    rgl_trace_builder_resource(b, RGL_RES_BYTES, bits, sizeof bits, &bm);
    eval_len = 0;
    EV(Viewport, 0, 0, 32, 32);
    EV(Color3f, 1, 1, 0);
    EV(RasterPos2f, 0.25, -0.5);
    EV(Bitmap, 8, 2, 0.5, 0, 9, 0, bm);
    EV(Bitmap, 0, 0, 0, 0, 9, 1, 0);
    EV(PixelZoom, 2, -3);
    EV(PixelTransferf, 0x0D14, 0.5); /* GL_RED_SCALE */
    EV(DrawPixels, 2, 2, 0x1908, 0x1401, px); /* GL_RGBA, GL_UNSIGNED_BYTE */
    EV(WindowPos2i, 4, 20);
    EV(CopyPixels, 0, 0, 2, 2, 0x1800, px); /* GL_COLOR */
    if (rgl_trace_builder_frame(b, 0, 0, 0, 0, seq, eval_len) == RGL_OK &&
        rgl_trace_builder_finish(b, true, &data, &size) == RGL_OK)
        rc = write_file(dir, "pixels.bin", data, size);
    rgl_trace_builder_destroy(b);
    return rc;
}

/* ---- Accumulation: passes that jitter the projection, then GL_RETURN ------------- */

static int write_accum(const char *dir)
{
    eval_len = 0;
    EV(ClearAccum, 0, 0, 0, 0);
    EV(Clear, 0x0200);
    for (int i = 0; i < 3; i++) {
        double d = (i - 1) * 0.004;
        EV(Clear, 0x4100);
        EV(MatrixMode, 0x1701);
        eval_cmd(RGL_OP_LoadIdentity, NULL, 0, NULL, 0);
        EV(Frustum, -1 + d, 1 + d, -0.75 + d, 0.75 + d, 1, 30);
        EV(MatrixMode, 0x1700);
        eval_cmd(RGL_OP_LoadIdentity, NULL, 0, NULL, 0);
        EV(Translatef, i == 2 ? 0.05 : 0, 0, 0); /* the last pass moves: a lens or motion */
        EV(Begin, 4);
        EV(Vertex3f, -1, -1, -5);
        EV(Vertex3f, 1, -1, -5);
        EV(Vertex3f, 0, 1, -6);
        eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
        EV(Accum, i == 0 ? 0x0101 : 0x0100, 1.0 / 3);
    }
    EV(Accum, 0x0103, 0.5);
    EV(Accum, 0x0102, 2);
    return write_file(dir, "accum-passes.bin", seq, eval_len);
}

/* ---- Render modes, names and the scissor box ------------------------------------ */

/* A picking pass (its draws and clear left out), named draws in GL_RENDER
 * mode, scissored clears and scissored geometry, through a perspective
 * camera; random sequences rarely reach GL_SELECT with a buffer. */
static int write_select(const char *dir)
{
    eval_len = 0;
    EV(Viewport, 0, 0, 320, 240);
    EV(Frustum, -1, 1, -0.75, 0.75, 1, 20);
    EV(SelectBuffer, 64);
    EV(RenderMode, 0x1C02, 0); /* GL_SELECT */
    eval_cmd(RGL_OP_InitNames, NULL, 0, NULL, 0);
    EV(PushName, 1);
    EV(Clear, 0x4000);
    EV(Rectf, -5, -5, 5, 5);
    EV(RenderMode, 0x1C00, 1); /* GL_RENDER: one hit */
    EV(FeedbackBuffer, 32, 0x0602); /* GL_3D_COLOR */
    EV(RenderMode, 0x1C01, 0);
    EV(PassThrough, 7);
    EV(Rectf, -1, -1, 1, 1);
    EV(RenderMode, 0x1C00, 9);
    EV(PushName, 2);
    EV(PushName, 3);
    EV(Translatef, 0, 0, -5);
    EV(Rectf, -1, -1, 1, 1);
    EV(LoadName, 4);
    EV(Enable, 0x0C11); /* GL_SCISSOR_TEST */
    EV(Scissor, 40, 30, 100, 80);
    EV(ClearColor, 1, 0.5, 0, 1);
    EV(Clear, 0x4000);
    EV(Rectf, -2, -2, 0, 0);
    EV(SolidSphere, 1, 12, 8);
    EV(Begin, 0x0001); /* GL_LINES */
    EV(Vertex2f, 0, 0);
    EV(Vertex2f, 1, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    eval_cmd(RGL_OP_PopName, NULL, 0, NULL, 0);
    EV(Scissor, 400, 0, 10, 10);
    EV(Rectf, -1, -1, 1, 1);
    return write_file(dir, "select-scissor.bin", seq, eval_len);
}

/* ---- Multitexture: two units, their state, coordinates and arrays ---------------- */

static int write_mtex(const char *dir)
{
    static const double quad[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const double st1[8] = {0.1, 0, 1, 0.2, 0.9, 1, 0, 0.8};
    eval_len = 0;
    EV(Ortho, -1, 2, -1, 2, -1, 1);
    EV(ActiveTexture, 0x84C1); /* GL_TEXTURE1 */
    EV(Enable, 0x0DE1);        /* GL_TEXTURE_2D */
    EV(TexEnvi, 0x2300, 0x2200, 0x0104); /* GL_ADD */
    EV(TexGeni, 0x2000, 0x2500, 0x2401); /* s: GL_OBJECT_LINEAR */
    EV(Enable, 0x0C60);
    EV(MatrixMode, 0x1702);
    EV(Rotatef, 30, 0, 0, 1);
    EV(MatrixMode, 0x1700);
    EV(ActiveTextureARB, 0x84C0);
    EV(Enable, 0x0DE1);
    EV(ActiveTexture, 0x84E0); /* GL_TEXTURE0 + 32: refused */
    EV(Begin, 0x0007);
    EV(MultiTexCoord2f, 0x84C1, 0, 1);
    EV(MultiTexCoord4dvARB, 0x84C0, 1, 2, 3, 1);
    EV(MultiTexCoord1s, 0x84C2, 3);
    EV(Vertex2f, 0, 0);
    EV(MultiTexCoord3iv, 0x84C1, 1, 0, 0);
    EV(Vertex2f, 1, 0);
    EV(Vertex2f, 1, 1);
    EV(Vertex2f, 0, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(ClientActiveTexture, 0x84C1);
    eval_cmd(RGL_OP_ArrayData, (const double[]){0x8078, 0, 2, 0x1406}, 4, st1, 8);
    EV(ClientActiveTextureARB, 0x84C0);
    eval_cmd(RGL_OP_ArrayData, (const double[]){0x8074, 0, 2, 0x1406}, 4, quad, 8);
    EV(DrawArrays, 0x0007, 0, 4);
    return write_file(dir, "mtex.bin", seq, eval_len);
}

/* ---- GLU NURBS: knots and points that fit their sizes ----------------------------- */

/* Appends command `op` with scalars v in row order and its blobs, in order,
 * from the float arrays b[0..] of n[0..] values. */
static void nurbs_cmd(uint32_t op, const double *v, size_t nv, const float *const *b,
                      const size_t *n)
{
    static rgl_cmd cmd;
    static uint8_t blob[3][1024];
    if (rgl_cmd_init(&cmd, op) != RGL_OK)
        return;
    size_t used = 0, nb = 0;
    for (uint32_t k = 0; k < cmd.nargs; k++) {
        rgl_arg *a = &cmd.arg[k];
        if (a->kind == RGL_ARG_BLOB) {
            for (size_t i = 0; i < n[nb]; i++)
                rgl_put_f(blob[nb] + 4 * i, b[nb][i]);
            a->bytes = blob[nb];
            a->count = (uint32_t)(4 * n[nb]);
            nb++;
        } else if (a->kind == RGL_ARG_ARRAY) {
            static double arr[RGL_MAX_ARGS][16];
            for (uint32_t c = 0; c < a->count; c++)
                arr[k][c] = c % 5 == 0 ? 1 : 0;
            a->array = arr[k];
        } else if (a->type == RGL_T_f) {
            a->v.f = used < nv ? v[used++] : 0;
        } else if (a->type == RGL_T_i) {
            a->v.i = used < nv ? (int64_t)v[used++] : 0;
        } else {
            a->v.u = used < nv ? (uint64_t)v[used++] : 0;
        }
    }
    eval_len += rgl_cmd_encode(&cmd, seq + eval_len, sizeof seq - eval_len);
}

static int write_nurbs(const char *dir)
{
    static const float k4[8] = {0, 0, 0, 0, 1, 1, 1, 1}, k2[4] = {0, 0, 1, 1};
    static const float kc[7] = {0, 0, 0, 0.5f, 1, 1, 1};
    static const float outer[10] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
    static const float hole[10] = {0.3f, 0.3f, 0.3f, 0.7f, 0.7f, 0.7f, 0.7f, 0.3f, 0.3f, 0.3f};
    static const float hk[7] = {0, 0, 1, 2, 3, 4, 4};
    float hill[48], col[16], curve[16];
    for (int i = 0; i < 16; i++) {
        hill[3 * i] = (float)(i / 4) - 1.5f;
        hill[3 * i + 1] = (float)(i % 4) - 1.5f;
        hill[3 * i + 2] = (i / 4 == 1 || i / 4 == 2) && (i % 4 == 1 || i % 4 == 2) ? 1.5f : -1;
        col[i] = (float)(i % 5) * 0.25f;
        curve[i] = i % 4 == 3 ? 1 + (float)(i / 8) : (float)i * 0.2f;
    }
    eval_len = 0;
    EV(Ortho, -3, 3, -3, 3, -5, 5);
    EV(Enable, 0x0D80); /* GL_AUTO_NORMAL */
    EV(Enable, 0x0B50); /* GL_LIGHTING */
    EV(NewNurbsRenderer, 1);
    EV(NurbsProperty, 1, 100205, 100217); /* GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE */
    EV(NurbsProperty, 1, 100206, 4);      /* GLU_U_STEP */
    EV(BeginSurface, 1);
    nurbs_cmd(RGL_OP_NurbsSurface, (const double[]){1, 8, 8, 12, 3, 4, 4, 0x0DB7}, 8,
              (const float *const[]){k4, k4, hill}, (const size_t[]){8, 8, 48});
    nurbs_cmd(RGL_OP_NurbsSurface, (const double[]){1, 4, 4, 8, 4, 2, 2, 0x0DB0}, 8,
              (const float *const[]){k2, k2, col}, (const size_t[]){4, 4, 16});
    EV(BeginTrim, 1);
    nurbs_cmd(RGL_OP_PwlCurve, (const double[]){1, 5, 2, 100210}, 4,
              (const float *const[]){outer}, (const size_t[]){10});
    EV(EndTrim, 1);
    EV(BeginTrim, 1);
    nurbs_cmd(RGL_OP_NurbsCurve, (const double[]){1, 7, 2, 2, 100210}, 5,
              (const float *const[]){hk, hole}, (const size_t[]){7, 10});
    EV(EndTrim, 1);
    EV(EndSurface, 1);
    EV(NurbsProperty, 1, 100204, 100240); /* GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON */
    EV(BeginSurface, 1);
    nurbs_cmd(RGL_OP_NurbsSurface, (const double[]){1, 8, 8, 12, 3, 4, 4, 0x0DB7}, 8,
              (const float *const[]){k4, k4, hill}, (const size_t[]){8, 8, 48});
    EV(EndSurface, 1);
    EV(BeginCurve, 1);
    nurbs_cmd(RGL_OP_NurbsCurve, (const double[]){1, 7, 4, 3, 0x0D98}, 5,
              (const float *const[]){kc, curve}, (const size_t[]){7, 16});
    EV(EndCurve, 1);
    nurbs_cmd(RGL_OP_LoadSamplingMatrices, (const double[]){1, 0, 0, 64, 64}, 5, NULL, NULL);
    EV(NurbsProperty, 1, 100160, 100161); /* GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR */
    EV(BeginSurface, 1);
    EV(EndSurface, 1);
    EV(DeleteNurbsRenderer, 1);
    return write_file(dir, "nurbs.bin", seq, eval_len);
}

/* ---- Texture copies, 3D, rectangle, packed, depth, points, provoking vertex ------- */

static int write_texcopy(const char *dir)
{
    static const uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
    static const uint8_t packed[8] = {0x00, 0xf8, 0xe0, 0x07, 0x1f, 0x00, 0xff, 0xff};
    static const uint8_t vox[24] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12,
                                    13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24};
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint32_t px = 0, pk = 0, vx = 0;
    const uint8_t *data;
    size_t size;
    int rc = 1;
    if (!b)
        return 1;
    rgl_trace_builder_resource(b, RGL_RES_BYTES, rgba, sizeof rgba, &px);
    rgl_trace_builder_resource(b, RGL_RES_BYTES, packed, sizeof packed, &pk);
    rgl_trace_builder_resource(b, RGL_RES_BYTES, vox, sizeof vox, &vx);
    eval_len = 0;
    EV(Ortho, -1, 2, -1, 2, -1, 1);
    EV(BindTexture, 0x0DE1, 1);
    EV(TexParameteri, 0x0DE1, 0x2801, 0x2600); /* GL_NEAREST */
    EV(CopyTexImage2D, 0x0DE1, 0, 0x1909, 0, 0, 2, 2, 0, px); /* GL_LUMINANCE */
    EV(CopyTexSubImage2D, 0x0DE1, 0, 1, 1, 0, 0, 1, 1, px);
    EV(CopyTexImage1D, 0x0DE0, 0, 0x1907, 0, 0, 4, 0, 0);
    EV(CopyTexSubImage1D, 0x0DE0, 0, 0, 0, 0, 1, 0);
    EV(TexParameteri, 0x0DE1, 0x2802, 0x8743); /* GL_MIRROR_CLAMP_TO_EDGE_EXT */
    EV(Enable, 0x0DE1);
    EV(Rectf, -1, -1, 1, 1);
    EV(TexImage2D, 0x0DE1, 0, 0x1907, 2, 2, 0, 0x1907, 0x8363, pk); /* 5_6_5 */
    EV(TexImage2D, 0x0DE1, 0, 0x81A5, 2, 1, 0, 0x1902, 0x1406, pk); /* depth, float */
    EV(TexParameteri, 0x0DE1, 0x884B, 0x8049);                    /* GL_INTENSITY */
    EV(BindTexture, 0x84F5, 2);                                   /* rectangle */
    EV(TexImage2D, 0x84F5, 0, 0x1908, 2, 2, 0, 0x1908, 0x1401, px);
    EV(Enable, 0x84F5);
    EV(Rectf, 0, 0, 2, 2);
    EV(BindTexture, 0x806F, 3); /* GL_TEXTURE_3D */
    EV(TexImage3D, 0x806F, 0, 0x1907, 2, 2, 2, 0, 0x1907, 0x1401, vx);
    EV(TexSubImage3D, 0x806F, 0, 0, 0, 1, 2, 2, 1, 0x1907, 0x1401, vx);
    EV(CopyTexSubImage3D, 0x806F, 0, 0, 0, 0, 0, 0, 1, 1, 0);
    EV(TexEnvi, 0x8861, 0x8862, 1);     /* GL_POINT_SPRITE, GL_COORD_REPLACE */
    EV(TexEnvf, 0x8500, 0x8501, 0.5);   /* GL_TEXTURE_LOD_BIAS */
    EV(ShadeModel, 0x1D00);
    EV(ProvokingVertex, 0x8E4D);
    EV(PointParameterfv, 0x8129, 1, 0.5, 0.25);
    EV(PointParameterf, 0x8126, 2);
    EV(PointParameteri, 0x8127, 9);
    EV(PointParameteriv, 0x8128, 3);
    EV(PointSize, 12);
    EV(Begin, 0x0000);
    EV(Vertex3f, 0, 0, -3);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(Begin, 0x0006);
    EV(Color3f, 1, 0, 0);
    EV(Vertex2f, 0, 0);
    EV(Color3f, 0, 1, 0);
    EV(Vertex2f, 1, 0);
    EV(Vertex2f, 1, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    if (rgl_trace_builder_frame(b, 0, 0, 0, 0, seq, eval_len) == RGL_OK &&
        rgl_trace_builder_finish(b, true, &data, &size) == RGL_OK)
        rc = write_file(dir, "texcopy.bin", data, size);
    rgl_trace_builder_destroy(b);
    return rc;
}

/* ---- Shapes and per-fragment tests: clip planes, offsets, masks, quadrics -------- */

static int write_shapes(const char *dir)
{
    eval_len = 0;
    EV(Translatef, 1, 0, -5);
    EV(ClipPlane, 0x3000, 1, 0, 0, 0.5); /* GL_CLIP_PLANE0 */
    EV(ClipPlane, 0x3007, 0, -1, 0, 1);
    EV(ClipPlane, 0x3008, 0, 0, 1, 0); /* past the eighth: rejected */
    EV(Enable, 0x3000);
    EV(Enable, 0x3007);
    EV(Enable, 0x8037); /* GL_POLYGON_OFFSET_FILL */
    EV(PolygonOffset, 1, 1);
    EV(NewQuadric, 1);
    EV(QuadricDrawStyle, 1, 100012); /* GLU_LINE */
    EV(Sphere, 1, 1, 8, 4);
    EV(SolidTeapot, 1);
    EV(Enable, 0x0B24); /* GL_LINE_STIPPLE */
    EV(LineStipple, 3, 0x1C47);
    EV(Begin, 0x0003); /* GL_LINE_STRIP */
    EV(Vertex2f, -2, 0);
    EV(Vertex2f, 2, 1);
    EV(Vertex2f, 0, -3);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(Begin, 0x0000); /* GL_POINTS */
    EV(Vertex2f, -0.75, 0);
    EV(Vertex2f, 0.75, 0);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(ClearStencil, 0);
    EV(Clear, 0x0400); /* GL_STENCIL_BUFFER_BIT */
    EV(Enable, 0x0B90); /* GL_STENCIL_TEST */
    EV(StencilFunc, 0x0207, 1, 255); /* GL_ALWAYS */
    EV(StencilOp, 0x1E00, 0x1E00, 0x1E01); /* GL_KEEP, GL_KEEP, GL_REPLACE */
    EV(StencilMask, 255);
    EV(ColorMask, 0, 0, 0, 0);
    EV(Rectf, -1, -1, 1, 1);
    EV(ColorMask, 1, 1, 1, 1);
    EV(StencilFunc, 0x0202, 1, 255); /* GL_EQUAL */
    EV(Rectf, -2, -2, 2, 2);
    EV(StencilFunc, 0x0205, 1, 255); /* GL_NOTEQUAL */
    EV(SolidSphere, 1, 12, 8);
    /* Two-sided stencil (format 1.4): back faces tested and written apart. */
    EV(StencilFuncSeparate, 0x0405, 0x0202, 1, 255); /* GL_BACK, GL_EQUAL */
    EV(StencilOpSeparate, 0x0405, 0x1E00, 0x1E00, 0x1E01); /* GL_BACK, KEEP, KEEP, REPLACE */
    EV(StencilMaskSeparate, 0x0404, 0); /* GL_FRONT */
    EV(Rectf, 2, -2, -2, 2); /* clockwise: a back face */
    return write_file(dir, "shapes.bin", seq, eval_len);
}

/* ---- Polygon stipple: a mask resource, stippled faces and solids ---------------- */

static int write_pstipple(const char *dir)
{
    uint8_t mask[128];
    for (int i = 0; i < 128; i++)
        mask[i] = (i / 4) % 2 ? 0x55 : 0xaa;
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint32_t m = 0;
    const uint8_t *data;
    size_t size;
    int rc = 1;
    if (!b)
        return 1;
    rgl_trace_builder_resource(b, RGL_RES_BYTES, mask, sizeof mask, &m);
    eval_len = 0;
    EV(Viewport, 5, 40, 64, 48);
    EV(Frustum, -1, 1, -1, 1, 1, 10);
    EV(Enable, 0x0B42); /* GL_POLYGON_STIPPLE */
    EV(PolygonStipple, m);
    EV(Rectf, -3, -3, 3, 3);
    EV(Begin, 0x0004); /* GL_TRIANGLES; the call inside is refused */
    EV(PolygonStipple, 0);
    EV(Vertex3f, -1, -1, -3);
    EV(Vertex3f, 1, -1, -4);
    EV(Vertex3f, 0, 1, -5);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(SolidSphere, 1, 12, 8);
    EV(PolygonStipple, 0);
    EV(PolygonStipple, m + 7); /* no such resource */
    EV(Disable, 0x0B42);
    EV(Rectf, -1, -1, 1, 1);
    if (rgl_trace_builder_frame(b, 0, 0, 0, 0, seq, eval_len) == RGL_OK &&
        rgl_trace_builder_finish(b, true, &data, &size) == RGL_OK)
        rc = write_file(dir, "pstipple.bin", data, size);
    rgl_trace_builder_destroy(b);
    return rc;
}

/* ---- Fog coordinates, secondary colours and their arrays; lit raster ------------ */

static int write_fogsec(const char *dir)
{
    static const double quad[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const double fog[4] = {0, 3, 6, 12};
    static const double sec[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0.5, 0.5};
    eval_len = 0;
    EV(Ortho, -1, 2, -1, 2, -1, 1);
    EV(Fogi, 0x8450, 0x8451); /* GL_FOG_COORD_SRC GL_FOG_COORD */
    EV(Fogi, 0x0B65, 0x2601); /* GL_LINEAR */
    EV(Enable, 0x0B60);       /* GL_FOG */
    EV(Enable, 0x8458);       /* GL_COLOR_SUM */
    EV(Begin, 0x0004);
    EV(FogCoordf, 2);
    EV(SecondaryColor3f, 0.2, 0.1, 0);
    EV(Vertex2f, 0, 0);
    EV(FogCoorddEXT, 5);
    EV(Vertex2f, 1, 0);
    EV(Vertex2f, 0, 1);
    eval_cmd(RGL_OP_End, NULL, 0, NULL, 0);
    EV(FogCoordPointer, 0x1406, 0);
    EV(SecondaryColorPointerEXT, 3, 0x1406, 0);
    EV(EnableClientState, 0x8457);
    EV(EnableClientState, 0x845E);
    eval_cmd(RGL_OP_ArrayData, (const double[]){0x8074, 0, 2, 0x1406}, 4, quad, 8);
    eval_cmd(RGL_OP_ArrayData, (const double[]){0x8457, 0, 1, 0x1406}, 4, fog, 4);
    eval_cmd(RGL_OP_ArrayData, (const double[]){0x845E, 0, 3, 0x1406}, 4, sec, 12);
    EV(DrawArrays, 0x0007, 0, 4);
    EV(Enable, 0x0B50); /* GL_LIGHTING: a lit raster position */
    EV(Enable, 0x4000);
    EV(RasterPos3f, 0.5, 0.5, 0);
    EV(Enable, 0x0B71); /* GL_DEPTH_TEST */
    EV(SolidSphere, 0.5, 16, 8);
    return write_file(dir, "fogsec.bin", seq, eval_len);
}

/* ---- EXT names of texture calls; cube-map and per-unit snapshot bindings ---- */

static int write_snaptex(const char *dir)
{
    static const uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 9};
    rgl_trace_builder *b = rgl_trace_builder_create();
    uint32_t px = 0;
    const uint8_t *data;
    size_t size;
    int rc = 1;
    if (!b)
        return 1;
    rgl_trace_builder_resource(b, RGL_RES_BYTES, rgba, sizeof rgba, &px);
    eval_len = 0;
    EV(Ortho, -1, 2, -1, 2, -1, 1);
    EV(BindTextureEXT, 0x0DE1, 1);
    EV(TexParameteri, 0x0DE1, 0x2801, 0x2600); /* GL_NEAREST */
    EV(CopyTexImage2DEXT, 0x0DE1, 0, 0x1908, 0, 0, 2, 2, 0, px);
    EV(CopyTexSubImage2DEXT, 0x0DE1, 0, 1, 1, 0, 0, 1, 1, px);
    EV(TexSubImage2DEXT, 0x0DE1, 0, 0, 0, 1, 1, 0x1908, 0x1401, px);
    EV(CopyTexImage1DEXT, 0x0DE0, 0, 0x1908, 0, 0, 4, 0, px);
    EV(CopyTexSubImage1DEXT, 0x0DE0, 0, 0, 0, 0, 1, 0);
    EV(BindTextureEXT, 0x806F, 2); /* GL_TEXTURE_3D */
    EV(TexImage3DEXT, 0x806F, 0, 0x1908, 2, 1, 2, 0, 0x1908, 0x1401, px);
    EV(TexSubImage3DEXT, 0x806F, 0, 0, 0, 1, 1, 1, 1, 0x1908, 0x1401, px);
    EV(CopyTexSubImage3DEXT, 0x806F, 0, 0, 0, 0, 0, 0, 1, 1, 0);
    EV(BlendEquationEXT, 0x8006); /* GL_FUNC_ADD */
    /* A snapshot's cube map and a binding on unit 1. */
    EV(BindTexture, 0x8513, 3);
    EV(TexImage2D, 0x8515, 0, 0x1908, 1, 1, 0, 0x1908, 0x1401, px);
    EV(TexImage2D, 0x851A, 0, 0x1908, 1, 1, 0, 0x1908, 0x1401, px);
    EV(ActiveTexture, 0x84C1);
    EV(BindTexture, 0x806F, 2);
    EV(Enable, 0x806F);
    EV(ActiveTexture, 0x84C0);
    EV(Enable, 0x0DE1);
    EV(Rectf, -1, -1, 1, 1);
    if (rgl_trace_builder_frame(b, 0, 0, 0, 0, seq, eval_len) == RGL_OK &&
        rgl_trace_builder_finish(b, true, &data, &size) == RGL_OK)
        rc = write_file(dir, "snaptex.bin", data, size);
    rgl_trace_builder_destroy(b);
    return rc;
}

int main(int argc, char **argv)
{
    rng r = {0x5eed5eed12345678ull};
    size_t nrows, row = 0, len;
    char name[64];
    int rc = 0;

    if (argc != 2) {
        fprintf(stderr, "usage: gen-corpus DIR\n");
        return 2;
    }
    rgl_cmd_info_all(&nrows);
    rc |= write_trace(&r, argv[1], "trace-index.bin", true, 64);
    rc |= write_trace(&r, argv[1], "trace-noindex.bin", false, 64);
    rc |= write_trace(&r, argv[1], "trace-small.bin", true, 256);
    /* Bare command sequences, a slice of the table each. */
    for (int k = 0; row < nrows; k++) {
        len = random_sequence(&r, row, 32, &row);
        snprintf(name, sizeof name, "seq-%02d.bin", k);
        rc |= write_file(argv[1], name, seq, len);
    }
    rc |= write_eval(argv[1]);
    rc |= write_pixels(argv[1]);
    rc |= write_accum(argv[1]);
    rc |= write_select(argv[1]);
    rc |= write_mtex(argv[1]);
    rc |= write_nurbs(argv[1]);
    rc |= write_texcopy(argv[1]);
    rc |= write_shapes(argv[1]);
    rc |= write_fogsec(argv[1]);
    rc |= write_snaptex(argv[1]);
    rc |= write_pstipple(argv[1]);
    return rc;
}
