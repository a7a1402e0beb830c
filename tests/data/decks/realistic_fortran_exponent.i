two shells, densities and radii in Fortran exponent form without the letter
1 1 4.5-2  -1       imp:n=1
2 2 -7.9+0 1 -2    imp:n=1
3 0         2       imp:n=0

1 so 5.0-1
2 so 1.0+1

m1 92235 1
m2 26056 1
