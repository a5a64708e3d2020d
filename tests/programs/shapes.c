/* shapes.c: small shapes drawn with raygl* calls (see shapes.h). */
#include "shapes.h"

#include "raygl.h"

const GLfloat shape_face_colors[6][3] = {
    {0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.9f},
    {0.9f, 0.8f, 0.2f}, {0.8f, 0.3f, 0.8f}, {0.3f, 0.8f, 0.8f},
};

void shape_cube(const GLfloat colors[6][3])
{
    static const GLfloat v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{1, 2, 6, 5}, {0, 4, 7, 3}, {3, 7, 6, 2},
                                {0, 1, 5, 4}, {4, 5, 6, 7}, {0, 3, 2, 1}};
    rayglBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        rayglColor3fv(colors[i]);
        for (int k = 0; k < 4; k++)
            rayglVertex3fv(v[f[i][k]]);
    }
    rayglEnd();
}

void shape_rect(GLfloat x0, GLfloat y0, GLfloat x1, GLfloat y1)
{
    rayglBegin(GL_QUADS);
    rayglVertex2f(x0, y0);
    rayglVertex2f(x1, y0);
    rayglVertex2f(x1, y1);
    rayglVertex2f(x0, y1);
    rayglEnd();
}
