// The proof that a CHASLES_SANITIZE build checks what it claims: each mode
// commits one error that only a sanitizer sees (a read of freed memory:
// AddressSanitizer; a signed overflow: UndefinedBehaviorSanitizer), and ctest expects the sanitizer's report and no
// line printed after it (-fno-sanitize-recover=all: the first report ends
// the process). A build without the sanitizers fails these tests.
#include <climits>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  volatile int index = 4;  // volatile: the compiler cannot see the error coming
  if (std::strcmp(argv[1], "use-after-free") == 0) {
    int* a = new int[8]();
    int* volatile alias = a;  // hides the use after free from the compiler's own warning
    delete[] a;
    const int v = alias[index];
    std::printf("continued after the read: %d\n", v);
    return 0;
  }
  if (std::strcmp(argv[1], "signed-overflow") == 0) {
    volatile int big = INT_MAX;
    const int r = big + index;
    std::printf("continued after the overflow: %d\n", r);
    return 0;
  }
  return 2;
}
