/* Prints a digest of the bits of many results: compositions, decompositions and conversions
 * of pseudo-random angles (ordinary, right, whole degrees, huge) in all 24 conventions, and
 * CYCLE600. c_tests/run.sh builds it against the std and the real-time library and requires
 * the same digest: the library computes its trigonometry itself, so every build gives the
 * same bits. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "cncrot.h"

static uint64_t digest = 14695981039346656037ull; /* FNV-1a */
static long results = 0;

static void take(const double *v, int n) {
  for (int i = 0; i < n; i++) {
    uint64_t bits;
    memcpy(&bits, &v[i], sizeof bits);
    for (int b = 0; b < 8; b++) {
      digest ^= (bits >> (8 * b)) & 0xff;
      digest *= 1099511628211ull;
    }
  }
  results++;
}

static uint64_t state = 0x9E3779B97F4A7C15ull;
static double angle(int kind) {
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  double u = (double)(state >> 11) / 9007199254740992.0;
  switch (kind % 4) {
  case 0: return 720.0 * u - 360.0;
  case 1: return 90.0 * (double)(int)(u * 9.0) - 360.0;
  case 2: return (double)(int)(u * 721.0) - 360.0;
  default: return (u - 0.5) * 1e7;
  }
}

int main(void) {
  static const int32_t codes[12] = {57, 45, 54, 30, 39, 27, 25, 29, 38, 46, 55, 59};
  for (int n = 0; n < 20000; n++) {
    int32_t intrinsic = n % 2, code = codes[(n / 2) % 12];
    double a[3] = {angle(n), angle(n + 1), angle(n + 2)}, m[9], out[3], conv[3];
    if (cncrot_matrix_from_angles(intrinsic, code, a, m) != 0) return 1;
    take(m, 9);
    int32_t s = cncrot_angles_from_matrix(1 - intrinsic, codes[(n / 24) % 12], m, out);
    if (s < 0) return 1;
    take(out, 3);
    s = cncrot_convert(intrinsic, code, a, intrinsic, codes[(n / 7) % 12], conv);
    if (s < 0) return 1;
    take(conv, 3);
  }
  struct cncrot_cycle600_gud gud;
  memset(&gud, 0, sizeof gud);
  if (cncrot_cycle600(&gud, NULL, 0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0,
                      0, 0) < 0)
    return 1;
  double cycle[3] = {gud.cyc600_2, gud.cyc600_3, gud.cyc600_4};
  take(cycle, 3);
  take(gud.frame, 16);
  printf("same_bits: %ld results, digest %016llx\n", results, (unsigned long long)digest);
  return 0;
}
