"""The sweep engine: definition -> grid -> dask map -> labelled netCDF dataset."""
