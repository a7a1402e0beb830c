errors in an included surface file
1 0 -10 -11 imp:n=1
2 0 -13 imp:n=1
3 0 10 imp:n=0

read file=cells_bad_surfaces.i noecho

