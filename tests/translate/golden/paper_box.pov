// paper_box.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{orthographic
 location <45,45,100.002>
 right <66.666664,0,0>
 up <0,50,0>
 direction <0,0,-1>
}
background{rgb<0,0,0>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<60,40,37.92893>,0}
mesh2{
vertex_vectors{12,
<10,-10,-10>,
<10,10,-10>,
<10,10,10>,
<10,-10,10>,
<-10,10,-10>,
<-10,10,10>,
<10,10,10>,
<10,10,-10>,
<-10,-10,10>,
<10,-10,10>,
<10,10,10>,
<-10,10,10>}
texture_list{3,
texture{pigment{rgb<0.9,0.2,0.2>}},
texture{pigment{rgb<0.2,0.8,0.3>}},
texture{pigment{rgb<0.2,0.4,0.9>}}}
face_indices{6,
<0,2,1>,0,
<0,3,2>,0,
<4,6,5>,1,
<4,7,6>,1,
<8,10,9>,2,
<8,11,10>,2}
matrix<0.853553,-0.146447,0.5,-0.146447,0.853553,0.5,-0.5,-0.5,0.707107,45,45,45>
}
clipped_by{plane{<0,0,1>,100.001}plane{<0,0,-1>,100}}
}
