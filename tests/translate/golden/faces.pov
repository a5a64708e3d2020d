// faces.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{orthographic
 location <100,50,1.01>
 right <200,0,0>
 up <0,100,0>
 direction <0,0,-1>
}
background{rgb<0,0,0.2>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<10,10,0.001>,0}
mesh2{
vertex_vectors{3,
<10,10,0>,
<50,10,0>,
<30,50,0>}
face_indices{1,
<0,2,1>}
texture{pigment{rgb<0,1,0>}}
matrix<1,0,0,0,1,0,0,0,1,0,0,0.001>
}
mesh2{
vertex_vectors{4,
<160,60,0>,
<190,60,0>,
<190,90,0>,
<160,90,0>}
face_indices{2,
<0,2,1>,
<0,3,2>}
texture{pigment{rgb<0.5,0.25,1>}}
matrix<1,0,0,0,1,0,0,0,1,0,0,0.004>
}
mesh2{
vertex_vectors{12,
<110,8.9627,0.003>,
<110,10.0480995,0.003>,
<150,10.0480995,0.003>,
<150,8.9627,0.003>,
<110,48.9627,0.003>,
<110,50.048103,0.003>,
<150,50.048103,0.003>,
<150,48.9627,0.003>,
<108.9627,10,0.003>,
<110.0481,10,0.003>,
<110.0481,50,0.003>,
<108.9627,50,0.003>}
face_indices{6,
<0,2,1>,
<0,3,2>,
<4,6,5>,
<4,7,6>,
<8,10,9>,
<8,11,10>}
texture{pigment{rgb<1,1,1>}}
}
clipped_by{plane{<0,0,1>,1.005}plane{<0,0,-1>,1}}
}
