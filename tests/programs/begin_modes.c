/* begin_modes.c: all ten glBegin modes, one per cell of a 5x2 grid.
 *
 * Top row: GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_POLYGON.
 * Bottom row: GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
 * GL_QUAD_STRIP.
 *
 * Built twice:
 *   begin_modes        GL_SMOOTH: every vertex of a filled mode has its own
 *                      colour, interpolated as GL does (so the triangulation
 *                      of strips, fans, quads, quad strips and polygons shows);
 *                      points have one colour per vertex, each line mode one
 *                      colour for the whole primitive.
 *   begin_modes_flat   (BEGIN_MODES_FLAT) GL_FLAT: every vertex, lines
 *                      included, has its own colour, so each primitive shows
 *                      its provoking vertex: the last vertex of each
 *                      triangle, quad, segment (line loop's closing segment:
 *                      the first vertex) and the first vertex of GL_POLYGON.
 *   texcopy_provoking  (BEGIN_MODES_FIRST too) GL_FLAT with
 *                      glProvokingVertex(GL_FIRST_VERTEX_CONVENTION): the
 *                      first vertex of each primitive, the second of a
 *                      fan's triangle (GL 3.2 table 2.12).
 *
 * Points are 6 pixels, lines 3 pixels wide; positions sit at .13/.37 of a
 * pixel so no edge runs through pixel centres at 320x240.
 */
#include "harness.h"

#include "raygl.h"

#ifdef BEGIN_MODES_FLAT
#define FLAT 1
#else
#define FLAT 0
#endif

static const GLfloat palette[8][3] = {
    {1.0f, 0.1f, 0.1f}, {0.1f, 0.9f, 0.2f}, {0.2f, 0.3f, 1.0f}, {1.0f, 0.9f, 0.1f},
    {0.9f, 0.2f, 0.9f}, {0.1f, 0.9f, 0.9f}, {1.0f, 0.6f, 0.2f}, {0.6f, 0.6f, 0.6f},
};

/* Each cell is 64x120 in the 320x240 logical space; coordinates below are
 * local to the cell. */
typedef struct { GLfloat x, y; } pt;

static void emit(GLenum mode, int cell, const pt *v, int n, int per_vertex)
{
    rayglPushMatrix();
    rayglTranslatef((GLfloat)(64 * (cell % 5)), cell < 5 ? 120.0f : 0.0f, 0.0f);
    rayglBegin(mode);
    for (int i = 0; i < n; i++) {
        rayglColor3fv(palette[(per_vertex ? cell + i : cell) % 8]);
        rayglVertex2f(v[i].x, v[i].y);
    }
    rayglEnd();
    rayglPopMatrix();
}

#define EMIT(mode, cell, arr, pv) emit(mode, cell, arr, (int)(sizeof arr / sizeof arr[0]), pv)

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);

    rayglClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglShadeModel(FLAT ? GL_FLAT : GL_SMOOTH);
#ifdef BEGIN_MODES_FIRST
    rayglProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
#endif
    rayglPointSize(6.0f);
    rayglLineWidth(3.0f);

    static const pt points[] = {{12, 20}, {32, 36}, {52, 20}, {12, 100}, {32, 84}, {52, 100}};
    static const pt lines[] = {{6, 10}, {58, 30}, {6, 50}, {58, 52}, {10, 70}, {54, 110}};
    static const pt strip[] = {{8, 10}, {56, 30}, {8, 55}, {56, 80}, {8, 110}};
    static const pt loop[] = {{32, 88}, {9, 67}, {18, 38}, {46, 38}, {55, 67}};
    static const pt polygon[] = {{32, 92}, {10, 76}, {10, 44}, {32, 28}, {54, 44}, {54, 76}};
    static const pt tris[] = {{6, 8}, {58, 12}, {30, 55}, {8, 65}, {56, 62}, {34, 112}};
    static const pt tstrip[] = {{8, 8}, {56, 14}, {10, 40}, {54, 46}, {8, 75}, {56, 80}, {12, 112}};
    static const pt fan[] = {{10, 10}, {58, 14}, {56, 50}, {46, 80}, {30, 104}, {12, 112}};
    static const pt quads[] = {{6, 8}, {58, 10}, {56, 52}, {8, 50}, {10, 64}, {54, 60}, {58, 112}, {6, 108}};
    static const pt qstrip[] = {{6, 8}, {58, 10}, {8, 45}, {56, 50}, {6, 80}, {58, 78}, {10, 112}, {54, 110}};

    EMIT(GL_POINTS, 0, points, 1);
    EMIT(GL_LINES, 1, lines, FLAT);
    EMIT(GL_LINE_STRIP, 2, strip, FLAT);
    EMIT(GL_LINE_LOOP, 3, loop, FLAT);
    EMIT(GL_POLYGON, 4, polygon, 1);
    EMIT(GL_TRIANGLES, 5, tris, 1);
    EMIT(GL_TRIANGLE_STRIP, 6, tstrip, 1);
    EMIT(GL_TRIANGLE_FAN, 7, fan, 1);
    EMIT(GL_QUADS, 8, quads, 1);
    EMIT(GL_QUAD_STRIP, 9, qstrip, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
