one element filled twice by translated copies; the element has an overlap
1 0  -1         fill=5            imp:n=1
2 0  -2         fill=5 (20 0 0)   imp:n=1
3 0  -9 1 2                       imp:n=1
4 0   9                           imp:n=0
10 1 -10.0 -11          u=5   imp:n=1
11 0        -12          u=5   imp:n=1

1 so 5
2 s 20 0 0 5
9 so 50
11 so 2
12 so 3

m1 92235 1
