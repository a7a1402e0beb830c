10 RCC 0 0 0  0 0 10  3
20 SO 50
c the surfaces below are not used by any cell
30 RPP -1 1 -1 1 -1 1
31 BOX 0 0 0  1 0 0  0 1 0  0 0 1
