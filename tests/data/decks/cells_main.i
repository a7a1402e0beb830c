cells read from two files: a can in a sphere
c cell 1: the can, cell 2: the void around it up to the sphere, cell 3: the outside
1 1 -7.86 -10 imp:n=1
2 0 10 -20 imp:n=1
3 0 20 imp:n=0

read file=cells_surfaces.i

m1 26000 1
