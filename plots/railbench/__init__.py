"""railbench report figures, tables and generated documentation, from the HDF5 files the C++
workbench writes.

One command line, `plots/rbplot COMMAND ...` (the same as `python3 -m railbench COMMAND ...` with
plots/ on PYTHONPATH); the commands are listed in railbench/__main__.py.  Only numpy,
matplotlib (Agg) and h5py are used; no scipy.
"""
