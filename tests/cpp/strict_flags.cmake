# The warnings chasles' headers are kept free of, for the strict compile
# tests (tests/cpp/CMakeLists.txt and strict_headers.cmake): what a
# real-time controller's build may turn on, as errors. Sets
# CHASLES_STRICT_FLAGS (both compilers) and CHASLES_STRICT_CLANG_FLAGS
# (clang only).
set(CHASLES_STRICT_FLAGS
    -fno-exceptions -fno-rtti
    -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast -Wdouble-promotion
    -Wfloat-equal -Wcast-qual -Wundef -Werror)
set(CHASLES_STRICT_CLANG_FLAGS -Wextra-semi-stmt)
