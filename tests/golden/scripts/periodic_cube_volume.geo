// The periodic cube of periodic_cube.geo, meshed in 3D.
Include "periodic_cube.geo";
