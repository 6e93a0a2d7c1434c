# The speed-against-error plot's labels, thinned so that none is drawn over
# another: in each scene (a block of speed-error.dat, blocks split by blank
# lines) the defaults' label is kept first, then the front's from the
# fastest on; a label whose text would cover one already kept is left
# blank (speed-error.md's table has every row). Positions are taken as the
# plot draws them: ms on a log scale, PSNR linear, each as a share of the
# scene's range; a label runs right of its point.
#   awk -f tests/bench/speed-error-labels.awk speed-error.dat
# Columns: ms, PSNR, on the front, default, reference, "label".
function flush(    i, j, k, n, xmin, xmax, ymin, ymax, x, y, w, keep, order, t) {
	n = 0
	for (i = 1; i <= rows; i++) {
		if (ref[i])
			continue
		x = log(ms[i]) / log(10)
		if (!n++ || x < xmin) xmin = x
		if (n == 1 || x > xmax) xmax = x
		if (n == 1 || db[i] < ymin) ymin = db[i]
		if (n == 1 || db[i] > ymax) ymax = db[i]
	}
	if (xmax - xmin < 1e-9) xmax = xmin + 1
	if (ymax - ymin < 1e-9) ymax = ymin + 1
	# candidates: the defaults first, then the front by time
	n = 0
	for (i = 1; i <= rows; i++)
		if (!ref[i] && dflt[i])
			order[++n] = i
	for (i = 1; i <= rows; i++)
		if (!ref[i] && !dflt[i] && front[i]) {
			order[++n] = i
			for (j = n; j > 1 && !dflt[order[j - 1]] && ms[order[j]] < ms[order[j - 1]]; j--) {
				t = order[j]; order[j] = order[j - 1]; order[j - 1] = t
			}
		}
	k = 0
	for (j = 1; j <= n; j++) {
		i = order[j]
		x = (log(ms[i]) / log(10) - xmin) / (xmax - xmin)
		y = (db[i] - ymin) / (ymax - ymin)
		# the axes reach past the data (decades, offsets): a generous width
		w = 0.06 + 0.025 * (length(label[i]) - 2) + (dflt[i] ? 0.04 : 0)
		keep = 1
		for (t = 1; t <= k && keep; t++)
			if (y - ky[t] < 0.08 && ky[t] - y < 0.08 && x - kx[t] < kw[t] && kx[t] - x < w)
				keep = 0
		if (keep) {
			k++; kx[k] = x; ky[k] = y; kw[k] = w
			shown[i] = 1
		}
	}
	for (i = 1; i <= rows; i++)
		print head[i] " " (shown[i] ? label[i] : "\"\"")
	for (i = 1; i <= rows; i++)
		delete shown[i]
	rows = 0
}
/^[0-9.]+ / {
	rows++
	ms[rows] = $1; db[rows] = $2; front[rows] = $3; dflt[rows] = $4; ref[rows] = $5
	head[rows] = $1 " " $2 " " $3 " " $4 " " $5
	label[rows] = substr($0, index($0, "\""))
	next
}
{
	if (rows)
		flush()
	print
}
END {
	if (rows)
		flush()
}
