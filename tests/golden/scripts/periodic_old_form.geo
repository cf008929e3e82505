// The older periodicity form: the slave's curves listed against the master's; the transform
// (here a quarter turn about the z axis) follows from them.
Point(1)={1,0,0,.2}; Point(2)={2,0,0,.2}; Point(3)={2,0,1,.2}; Point(4)={1,0,1,.2};
Point(5)={0,1,0,.2}; Point(6)={0,2,0,.2}; Point(7)={0,2,1,.2}; Point(8)={0,1,1,.2};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1};
Line(5)={5,6}; Line(6)={6,7}; Line(7)={7,8}; Line(8)={8,5};
Curve Loop(1)={1,2,3,4}; Plane Surface(1)={1};
Curve Loop(2)={5,6,7,8}; Plane Surface(2)={2};
Periodic Surface 2 {5,6,7,8} = 1 {1,2,3,4};
