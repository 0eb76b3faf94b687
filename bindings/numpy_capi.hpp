// chasles._core: numpy's C API (arrays and ufuncs), shared by the
// translation units that register generalized ufuncs. module.cpp imports it
// once (import_array / import_umath); the others see the same table.
#pragma once

#define PY_ARRAY_UNIQUE_SYMBOL chasles_ARRAY_API
#define PY_UFUNC_UNIQUE_SYMBOL chasles_UFUNC_API
#ifndef CHASLES_PY_IMPORT_NUMPY
#define NO_IMPORT_ARRAY
#define NO_IMPORT_UFUNC
#endif
#define NPY_NO_DEPRECATED_API NPY_2_0_API_VERSION

#include <numpy/ndarrayobject.h>
#include <numpy/ndarraytypes.h>
#include <numpy/ufuncobject.h>
