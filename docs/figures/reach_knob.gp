# The reach knob of local interpolation in time (docs/interpolation.md, "Against the global
# solve"): solve time against the RMS and max deviation from the global solve, from the table of
# `vdfx bench --filter rbf.reach` there (4200 keyframes at the density of 100000 over 20 minutes).
#   gnuplot docs/figures/reach_knob.gp      (writes docs/figures/reach_knob.png)
set terminal pngcairo size 1100,450 font "DejaVu Sans,11"
set output "docs/figures/reach_knob.png"
# reach (s), solve (ms), max deviation, RMS deviation; block 0: c = 1, block 1: D = 2
$c1 << EOD
0.125 24.1 0.451 0.090
0.25 22.2 0.218 0.047
0.5 37.2 0.165 0.029
1 71.3 0.112 0.018
2 171 0.050 0.0090
4 448 0.024 0.0060
8 1390 0.015 0.0030
EOD
$d2 << EOD
0.125 19.8 2.61 0.88
0.5 35.3 2.33 0.65
2 231 1.13 0.23
4 618 0.391 0.061
8 1820 0.044 0.0064
EOD
set multiplot layout 1,2 title "Local interpolation's reach (labels, seconds): solve time against the deviation from the global solve (global: 1.4 to 2.8 s)"
set logscale xy
set xlabel "solve (ms, one run at load 7.6 on 2 shared cores)"
set grid
set key top right
set ylabel "RMS deviation (values 0..4)"
set title "RMS over 1000 random views"
plot $c1 using 2:4 with linespoints lw 2 pt 7 title "c = 1 (contract)", \
     $c1 using 2:4:(sprintf("%g", $1)) with labels offset 0,1 notitle, \
     $d2 using 2:4 with linespoints lw 2 pt 5 title "D = 2 deg/s (author)", \
     $d2 using 2:4:(sprintf("%g", $1)) with labels offset 0,-1 notitle
set ylabel "max deviation"
set title "max over the same views"
plot $c1 using 2:3 with linespoints lw 2 pt 7 title "c = 1 (contract)", \
     $c1 using 2:3:(sprintf("%g", $1)) with labels offset 0,1 notitle, \
     $d2 using 2:3 with linespoints lw 2 pt 5 title "D = 2 deg/s (author)", \
     $d2 using 2:3:(sprintf("%g", $1)) with labels offset 0,-1 notitle
unset multiplot
