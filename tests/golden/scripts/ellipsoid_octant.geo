// An octant of an ellipsoid (semi-axes 2, 1, 0.5): a filling surface of three ellipse arcs.
lc = 0.05;
Point(1)={0,0,0,lc}; Point(2)={2,0,0,lc}; Point(3)={0,1,0,lc}; Point(4)={0,0,0.5,lc};
Ellipse(1)={2,1,2,3}; Ellipse(2)={3,1,3,4}; Ellipse(3)={4,1,2,2};
Curve Loop(1)={1,2,3}; Surface(1)={1};
