/* conf_fog.h: the scene of conf_fog.c and conf_fog_start_end.c: unlit
 * rectangles at eye distances 2 to 14 under glOrtho (each rectangle one
 * distance, one fog factor), in window pixels, the background unfogged,
 * under the fog given. Included after <raygl/gl.h>. */
#ifndef RGL_TEST_CONF_FOG_H
#define RGL_TEST_CONF_FOG_H

static inline void conf_fog_rect(int x0, int y0, int x1, int y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f((float)x0 + 0.25f, (float)y0 + 0.25f, z);
    glVertex3f((float)x1 + 0.25f, (float)y0 + 0.25f, z);
    glVertex3f((float)x1 + 0.25f, (float)y1 + 0.25f, z);
    glVertex3f((float)x0 + 0.25f, (float)y1 + 0.25f, z);
    glEnd();
}

static inline void conf_fog_scene(int w, int h, GLint mode, float start, float end, float density)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.05f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_FOG);
    const GLfloat fogc[4] = {0.5f, 0.55f, 0.75f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    glFogi(GL_FOG_MODE, mode);
    glFogf(GL_FOG_START, start);
    glFogf(GL_FOG_END, end);
    glFogf(GL_FOG_DENSITY, density);
    static const float d[2][8] = {{2.0f, 3.5f, 5.0f, 6.5f, 7.8f, 8.3f, 8.8f, 10.0f},
                                  {11.0f, 11.9f, 12.5f, 13.0f, 13.5f, 14.0f, 4.0f, 9.5f}};
    for (int r = 0; r < 2; r++)
        for (int i = 0; i < 8; i++) {
            glColor3f(0.9f - 0.05f * (float)i, 0.35f + 0.07f * (float)i, 0.2f + 0.3f * (float)r);
            conf_fog_rect(6 + 39 * i, 16 + 110 * r, 39 + 39 * i, 110 + 110 * r, -d[r][i]);
        }
    glDisable(GL_FOG);
}

#endif
