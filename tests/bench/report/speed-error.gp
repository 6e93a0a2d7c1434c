# Time against error for each scene of speed-error.md, the front joined
# and the defaults circled; drawn by tests/bench/bench_quality.sh:
#   gnuplot -e "dir='tests/bench/report'" tests/bench/report/speed-error.gp
if (!exists("dir")) dir = "tests/bench/report"
dat = dir."/speed-error.dat"
front = dir."/speed-error-front.dat"
scenes = int(system("grep -c '^# ' ".dat))
# One cell per scene: three a row, as many rows as the scenes need (a
# fixed 3x3 drew the tenth scene over the first).
cols = 3
rows = (scenes + cols - 1) / cols
# The labels, thinned so that none covers another (speed-error-labels.awk).
labels = "< awk -f tests/bench/speed-error-labels.awk ".dat." 2>/dev/null"

set terminal pngcairo size 1600,440 * rows font ",9"
set output dir."/speed-error.png"
set multiplot layout rows,cols title "Median ms per frame (log) against PSNR (dB) to the highest quality: the front joined, the defaults circled (tests/bench/report/speed-error.md)"
set logscale x
set xlabel "ms per frame"
set ylabel "PSNR dB"
set grid
set key off
set offsets graph 0.05, graph 0.3, graph 0.08, graph 0.08
do for [i = 0:scenes - 1] {
	set title system(sprintf("sed -n 's/^# //p' %s | sed -n '%dp'", dat, i + 1))
	# columns: ms, PSNR, on the front, default, reference, label; the
	# reference (no error by definition) is left out
	plot front index i using 1:2 with lines lw 2 lc rgb "#1f77b4", \
	     dat index i using 1:($5 > 0 ? 1/0 : $2) with points pt 7 ps 0.7 lc rgb "#999999", \
	     dat index i using 1:($3 > 0 && $5 == 0 ? $2 : 1/0) with points pt 7 ps 0.9 lc rgb "#1f77b4", \
	     dat index i using 1:($4 > 0 ? $2 : 1/0) with points pt 6 ps 2.6 lw 2 lc rgb "#d62728", \
	     labels index i using 1:($3 > 0 && $4 == 0 && $5 == 0 ? $2 : 1/0):6 with labels font ",7" left offset 0.6,0.4 tc rgb "#333333", \
	     labels index i using 1:($4 > 0 ? $2 : 1/0):6 with labels font ",7" left offset 1.8,0.7 tc rgb "#d62728"
}
unset multiplot
