# The polar grid (included by in.tube): n rings across the wall, nt
# particles around each at equal angles: a strip of the lattice (column ->
# angle, row -> radius, layer -> axial position) wrapped into the tube.
# Each particle's volume is its cell, dx x r dtheta (x thickness, or x dx
# in 3D), so the cells fill the tube exactly.
region          strip block 0 ${nt} 0 ${n} INF INF
create_atoms    1 region strip
variable        j loop ${n}
label           row
region          row block INF INF $(v_j-1) ${j} INF INF
group           row region row
set             group row volume $(v_dx*(v_Ri+(v_j-0.5)*v_dx)*2*PI/v_nt*((v_dim==2)*v_L+(v_dim==3)*v_dx))
group           row delete
region          row delete
next            j
jump            SELF row
fix             strip all store/state 0 x y     # displace_atoms moves x before it evaluates y
variable        th atom 2*PI*f_strip[1]/(${nt}*${dx})
variable        ux atom (${Ri}+f_strip[2])*cos(v_th)-f_strip[1]
variable        uy atom (${Ri}+f_strip[2])*sin(v_th)-f_strip[2]
displace_atoms  all move v_ux v_uy 0 units box
unfix           strip
variable        vmean equal $(PI*(v_Ro^2-v_Ri^2)*v_L/count(all))
