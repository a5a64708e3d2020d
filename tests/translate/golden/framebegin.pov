// framebegin.pov: written by raygl2pov 0.1.0 from golden.raygl, frame 0 (stream 0, frame 0 of the stream)
// rayglFrameBegin name: ../../x?"}#fopen.pov
// Eye coordinates of the OpenGL frame: x right, y up, the camera looks down -z.
#version 3.7;
global_settings{assumed_gamma 2.2}
camera{perspective
 location <30,40,50>
 right <1.1433239,0,-0.6859943>
 up <-0.29104275,0.82462114,-0.48507124>
 direction <-0.51213205,-0.68284273,-0.8535534>
}
background{rgb<0,0,0>}
#default{finish{ambient 0 diffuse 0 emission 1}}
union{
sphere{<-9.998,-9.9975,10.002>,0}
mesh2{
vertex_vectors{4,
<-10,-10,10>,
<10,-10,10>,
<-10,10,10>,
<10,10,10>}
face_indices{2,
<0,2,1>,
<1,2,3>}
texture{pigment{rgb<0.2,0.4,0.9>}}
matrix<0.99995,0,0,0,0.99995,0,0,0,0.99995,0.0015,0.002,0.0025>
}
}
light_source{<100,100,100> rgb<1,1,1> parallel point_at<0,0,0>}
