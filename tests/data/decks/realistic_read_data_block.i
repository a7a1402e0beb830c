sphere whose material cards live in a file that is not here
1 1 -10.0  -1      imp:n=1
2 0        1       imp:n=0

1 so 3.0

read file=realistic_material_cards_not_here
nps 10
