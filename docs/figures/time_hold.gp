# Plots the output of build/vdfx_time_hold_figure (docs/interpolation.md, "Time"):
#   build/vdfx_time_hold_figure > /tmp/time_hold.csv && gnuplot -e "data='/tmp/time_hold.csv'" docs/figures/time_hold.gp
if (!exists("data")) data = "/tmp/time_hold.csv"
set terminal pngcairo size 1200,900 font "DejaVu Sans,11"
set output "docs/figures/time_hold.png"
set datafile separator ","
set multiplot layout 2,2 title "Exposure (stops) over the clip. Top: keyframes all at frame 0 (alternating +-1.4 stops), seen at azimuth -120, altitude 10"
set xlabel "frame (30 fps)"
set ylabel "stops"
set yrange [-1.6:1.6]
set key bottom right
set grid
set title "before: the paper (c = 1, no hold)"
plot for [i=0:4] data index 0 using 1:(column(2 + 2*i)) with lines lw 2 title sprintf("%s keyframes", word("1 2 3 4 10", i+1))
set title "after: vdfx (1 s = 2 deg, hold outside the span)"
plot for [i=0:4] data index 0 using 1:(column(3 + 2*i)) with lines lw 2 title sprintf("%s keyframes", word("1 2 3 4 10", i+1))
set xlabel "frame"
set key bottom left
set title "two sets at frames 0 and 100 (the second turned 90 deg), seen at azimuth 90"
plot data index 1 using 1:2 with lines lw 2 title "before (paper)", \
     data index 1 using 1:3 with lines lw 2 title "after (vdfx)"
set title "the same two sets, seen at azimuth -90"
plot data index 1 using 1:4 with lines lw 2 title "before (paper)", \
     data index 1 using 1:5 with lines lw 2 title "after (vdfx)"
unset multiplot
