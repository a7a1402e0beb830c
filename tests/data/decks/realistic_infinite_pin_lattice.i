square lattice of infinite pins in a bounded box; the pin fuel is wider than its clad
1 1 -10.0  -1               u=1 imp:n=1
2 2 -6.5    1 -2            u=1 imp:n=1
3 3 -1.0    2               u=1 imp:n=1
c the fuel radius 0.7 reaches past the clad radius 0.6: cells 1 and 3 overlap
4 0  -11 12 -13 14  lat=1 fill=1  u=2 imp:n=1
5 0  -21 22 -23 24 -25 26  fill=2 imp:n=1
6 0   21:-22:23:-24:25:-26        imp:n=0

1 cz 0.7
2 cz 0.6
11 px 1
12 px -1
13 py 1
14 py -1
21 px 5
22 px -5
23 py 5
24 py -5
25 pz 10
26 pz -10

m1 92235 1
m2 40090 1
m3 1001 2 8016 1
