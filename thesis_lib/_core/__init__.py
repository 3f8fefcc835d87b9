"""The compiled core: C++17 kernels (``src/<name>.cpp``) as extension modules ``thesis_lib._core.<name>``.

Each module holds the kernels of one concept of the thesis; the Python layer validates its input and
casts it to the dtypes and C order the kernels take, so that a kernel trusts what it is given.
"""
