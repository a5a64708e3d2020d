// lines_points.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{orthographic
 location <160,120,1.01>
 right <320,0,0>
 up <0,240,0>
 direction <0,0,-1>
}
background{rgb<0,0,0>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<20,20,0.001>,0}
mesh2{
vertex_vectors{16,
<20,18.5,0.001>,
<20,21.5,0.001>,
<150,41.5,0.001>,
<150,38.5,0.001>,
<200,19,0.002>,
<200,21,0.002>,
<300,31,0.002>,
<300,29,0.002>,
<299,30,0.002>,
<301,30,0.002>,
<251,120,0.002>,
<249,120,0.002>,
<249,120,0.002>,
<251,120,0.002>,
<201,20,0.002>,
<199,20,0.002>}
texture_list{4,
texture{pigment{rgb<1,0,0>}},
texture{pigment{rgb<0,0,1>}},
texture{pigment{rgb<0,1,1>}},
texture{pigment{rgb<1,1,0>}}}
face_indices{8,
<0,2,1>,0,1,0,
<0,3,2>,0,1,1,
<4,6,5>,2,
<4,7,6>,2,
<8,10,9>,2,
<8,11,10>,2,
<12,14,13>,3,
<12,15,14>,3}
}
clipped_by{plane{<0,0,1>,1.005}plane{<0,0,-1>,1}}
}
disc{<80.5,200.5,0.004>,<0,0,1>,2.5 texture{pigment{rgb<1,1,1>}}}
mesh2{
vertex_vectors{4,
<38,198,0.003>,
<43,198,0.003>,
<43,203,0.003>,
<38,203,0.003>}
face_indices{2,
<0,2,1>,
<0,3,2>}
texture{pigment{rgb<1,1,1>}}
}
