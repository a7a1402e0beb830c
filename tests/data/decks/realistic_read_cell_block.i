a READ in the cell block whose file is not here
1 0  -1  imp:n=1
read file=realistic_cell_cards_not_here
2 0   1  imp:n=0

1 so 3.0

nps 10
