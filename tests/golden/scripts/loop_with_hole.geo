// One curve loop holding the outer circle and, after it, the hole: an annulus.
Point(1)={0,0,0,0.1}; Point(2)={1,0,0,0.1}; Point(3)={0,1,0,0.1}; Point(4)={-1,0,0,0.1}; Point(5)={0,-1,0,0.1};
Point(6)={0.5,0,0,0.1}; Point(7)={0,0.5,0,0.1}; Point(8)={-0.5,0,0,0.1}; Point(9)={0,-0.5,0,0.1};
Circle(1)={2,1,3}; Circle(2)={3,1,4}; Circle(3)={4,1,5}; Circle(4)={5,1,2};
Circle(5)={6,1,7}; Circle(6)={7,1,8}; Circle(7)={8,1,9}; Circle(8)={9,1,6};
Curve Loop(1)={1,2,3,4,-5,-6,-7,-8}; Plane Surface(1)={1};
