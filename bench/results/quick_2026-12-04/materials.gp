set terminal pngcairo size 900,380 font ',10' noenhanced
set output 'bench/results/quick_2026-12-04/materials.png'
set datafile separator ','
set logscale xy
set grid
set key bottom left
set multiplot layout 1,2 title 'materials: RMSE against time and samples'
set xlabel 'seconds'
set ylabel 'RMSE'
plot 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'raylab' && strcol(3) eq 'mean' && $7 > 0 ? $5 : 1/0):7 with linespoints title 'raylab', 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'raylab:even' && strcol(3) eq 'mean' && $7 > 0 ? $5 : 1/0):7 with linespoints title 'raylab:even', 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'cycles' && strcol(3) eq '1' && $7 > 0 ? $5 : 1/0):7 with linespoints title 'cycles', 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'cycles:adaptive' && strcol(3) eq '1' && $7 > 0 ? $5 : 1/0):7 with linespoints title 'cycles:adaptive'
set xlabel 'samples per pixel'
plot 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'raylab' && strcol(3) eq 'mean' && $7 > 0 ? $4 : 1/0):7 with linespoints title 'raylab', 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'raylab:even' && strcol(3) eq 'mean' && $7 > 0 ? $4 : 1/0):7 with linespoints title 'raylab:even', 'bench/results/quick_2026-12-04/convergence.csv' using (strcol(1) eq 'materials' && strcol(2) eq 'cycles' && strcol(3) eq '1' && $7 > 0 ? $4 : 1/0):7 with linespoints title 'cycles'
unset multiplot
