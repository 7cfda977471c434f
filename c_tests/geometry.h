/* Hand geometry for the C tests, independent of the library: elementary rotations (with the
 * C library's trigonometry) and their products. */
#ifndef CNCROT_TEST_GEOMETRY_H
#define CNCROT_TEST_GEOMETRY_H

#include <math.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* Hand geometry, independent of the library: elementary rotations and products. */
static inline void elem(int axis, double deg, double r[9]) {
  double c = cos(deg * PI / 180), s = sin(deg * PI / 180);
  double x[9] = {1, 0, 0, 0, c, -s, 0, s, c}, y[9] = {c, 0, s, 0, 1, 0, -s, 0, c}, z[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
  memcpy(r, axis == 1 ? x : axis == 2 ? y : z, sizeof x);
}
static inline void mul3(const double a[9], const double b[9], double r[9]) {
  double t[9];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) t[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
  memcpy(r, t, sizeof t);
}
/* r = R_a(p)·R_b(q)·R_c(s): about the moving axes a, then b, then c. */
static inline void intrinsic(int a, int b, int c, double p, double q, double s, double r[9]) {
  double ra[9], rb[9], rc[9];
  elem(a, p, ra);
  elem(b, q, rb);
  elem(c, s, rc);
  mul3(ra, rb, r);
  mul3(r, rc, r);
}
static inline void rot_of(const double f[16], double r[9]) {
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) r[3 * i + j] = f[4 * i + j];
}

#endif
