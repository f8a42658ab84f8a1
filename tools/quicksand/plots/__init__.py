"""quicksand's plots as functions over a run's results: each module's plot(OUTPUT_DIR, out=None)
draws one figure into a PNG and returns its path and the figure, whose axes keep what was drawn
(tools/tests check the data against the files). The scripts tools/plot_*.py are their entry points.

  series        series.csv: filter velocities, gate pressure and head, sand surface, volumes
  profiles      fields.h5, one output: pore pressure, vertical effective stress, porosity along z
  pipes         fields.h5's cells and pipes.csv (2D, 3D): frames, pipes against time, a GIF
  fluidisation  series.csv and fields.h5: bed height, filter velocity, porosity along the column
                against time, the fluidised front and its fit (front_fit.csv); plot(argv) takes
                the command's options
"""
