set terminal pngcairo size 1000,640 font 'DejaVu Sans,10'
set output 'docs/bench/bench.png'
set title 'volren bench: default.osgt (ch2.nii.gz), 256x256 (EGL surfaceless: OpenGL 4.5 (Compatibility Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits))' noenhanced
set logscale xy
set grid
set key top right
set xlabel 'frame time, ms (median draw time)'
set ylabel 'RMSE against the CPU reference'
set label 'front over the configurations drawing the default lighting' at graph 0.02,0.04 font ',8'
plot 'docs/bench/bench-front.dat' using 1:2 with lines lw 2 lc rgb '#d62728' title 'Pareto front', \
     'docs/bench/bench-points.dat' using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4' title 'volren configurations', \
     'docs/bench/bench-points.dat' using 1:2:3 with labels offset char 0.6,0.6 left font ',8' noenhanced notitle, \
     'docs/bench/bench-peer.dat' using 1:2 with points pt 5 ps 1.6 lc rgb '#2ca02c' title 'VTK GPU ray caster', \
     'docs/bench/bench-peer.dat' using 1:2:3 with labels offset char 0.6,-0.8 left font ',8' noenhanced notitle
