shell with a cell on a surface that is not defined
1 1 -7.9  -1       imp:n=1
2 0       1 -2     imp:n=1
3 0       -7       imp:n=1
4 0       2        imp:n=0

1 so 5.0
2 so 10.0

m1 26056 1
nps 10
