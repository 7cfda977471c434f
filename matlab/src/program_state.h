/* The program state as a MATLAB struct (rotation, origin, angles, shift, active, dialect,
 * options, choice, reference_axis, seal) and back: shared by cncrot_program_lines and cncrot_program_axes. */
#ifndef CNCROT_PROGRAM_STATE_H
#define CNCROT_PROGRAM_STATE_H
#include "gateway.h"

static const char *FIELDS[] = {"rotation", "origin", "angles", "shift", "active", "dialect",
                               "options", "choice", "reference_axis", "seal"};

/* A field of the state struct as n doubles (absent: zeros; wrong size: an error). */
static void field(const mxArray *s, int arg, const char *name, double *out, size_t n) {
  memset(out, 0, n * sizeof *out);
  const mxArray *f = mxGetField(s, 0, name);
  if (!f) return;
  if (!mxIsDouble(f) || mxIsComplex(f) || mxIsSparse(f) || mxGetNumberOfElements(f) != n)
    fail("cncrot:badState", "%s: field %s must be %d real doubles", label(arg, "state"), name, (int)n);
  const double *d = real_data(f, arg, "state");
  memcpy(out, d, n * sizeof *out);
}

static int32_t as_int(double v) { return v >= -2147483648.0 && v <= 2147483647.0 ? (int32_t)v : INT32_MIN; }

/* A uint32 field given as a double (anything else: a value the library refuses). */
static uint32_t as_u32(double v) {
  return v >= 0 && v <= 4294967295.0 && v == (double)(uint32_t)v ? (uint32_t)v : 0xFFFFFFFFu;
}

/* The state struct as the library's; values the library did not write are refused by it
 * (cncrot:badState), after the call. A struct without a seal is a new program: only its
 * options may be set (struct('options', 1)), and cncrot_program_init seals it. */
static void from_struct(const mxArray *s, int arg, cncrot_program *p) {
  memset(p, 0, sizeof *p);
  if (mxIsEmpty(s) && !mxIsStruct(s)) return;
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    fail("cncrot:badClass", "%s must be a 1-by-1 struct from cncrot_program_lines, or []; got %s", label(arg, "state"), described(s));
  double r[9], v[3];
  field(s, arg, "rotation", r, 9);
  to_row_major(r, p->rotation);
  field(s, arg, "origin", p->origin, 3);
  field(s, arg, "angles", p->angles, 3);
  field(s, arg, "shift", p->shift, 3);
  field(s, arg, "choice", v, 1);
  p->choice = as_int(v[0]);
  field(s, arg, "reference_axis", v, 1);
  p->reference_axis = as_int(v[0]);
  field(s, arg, "active", v, 1);
  p->active = as_int(v[0]);
  field(s, arg, "dialect", v, 1);
  p->dialect = as_int(v[0]);
  /* The one field a user sets: any numeric class or logical (struct('options', int32(1))). */
  const mxArray *o = mxGetField(s, 0, "options");
  if (o && !mxIsDouble(o) && (mxIsNumeric(o) || mxIsLogical(o)) && !mxIsComplex(o) && !mxIsSparse(o) && mxGetNumberOfElements(o) == 1)
    v[0] = mxGetScalar(o);
  else field(s, arg, "options", v, 1);
  p->options = as_u32(v[0]);
  if (mxGetField(s, 0, "seal")) {
    field(s, arg, "seal", v, 1);
    p->reserved = as_u32(v[0]);
    return;
  }
  cncrot_program fresh;
  memset(&fresh, 0, sizeof fresh);
  fresh.options = p->options;
  if (memcmp(&fresh, p, sizeof fresh) == 0 && cncrot_program_init(p, fresh.options) < 0)
    fail("cncrot:badState", "%s: options %u is not a combination of cncrot program options", label(arg, "state"), (unsigned)fresh.options);
}

static mxArray *to_struct(const cncrot_program *p) {
  mxArray *s = mxCreateStructMatrix(1, 1, 10, FIELDS);
  mxArray *r = mxCreateDoubleMatrix(3, 3, mxREAL);
  to_col_major(p->rotation, mxGetDoubles(r));
  mxSetField(s, 0, "rotation", r);
  mxArray *o = mxCreateDoubleMatrix(1, 3, mxREAL), *a = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(o), p->origin, sizeof p->origin);
  memcpy(mxGetDoubles(a), p->angles, sizeof p->angles);
  mxSetField(s, 0, "origin", o);
  mxSetField(s, 0, "angles", a);
  mxArray *sh = mxCreateDoubleMatrix(1, 3, mxREAL);
  memcpy(mxGetDoubles(sh), p->shift, sizeof p->shift);
  mxSetField(s, 0, "shift", sh);
  mxSetField(s, 0, "choice", mxCreateDoubleScalar(p->choice));
  mxSetField(s, 0, "reference_axis", mxCreateDoubleScalar(p->reference_axis));
  mxSetField(s, 0, "active", mxCreateDoubleScalar(p->active));
  mxSetField(s, 0, "dialect", mxCreateDoubleScalar(p->dialect));
  mxSetField(s, 0, "options", mxCreateDoubleScalar(p->options));
  mxSetField(s, 0, "seal", mxCreateDoubleScalar(p->reserved));
  return s;
}

#endif
