"""Pictures of gearloss outputs, used by scripts/plot.py.

  data      reading a CSV (pandas) and its metadata sidecar, the kinds of file, clear errors
  labels    titles from the sidecar (case, oil, thermal mode, ratio) or from the CSV itself
  scale     colour levels (robust quantiles, --levels) and plain colour-bar numbers
  surface   a field over speed x torque: contours on the computed grid, points, failed region
  maps      `gearloss map` pictures (efficiency, oil temperature, breakdown), sweeps as facets
  compare   `gearloss compare` differences, one colour sense on every panel
  cycle     `gearloss cycle` time series: start, warm and pre-warmed runs overlaid
  diagnose  `gearloss diagnose --residuals` before/after
"""
