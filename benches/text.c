/* The text benchmark: cncrot's program-line writer and reader against glibc's snprintf and
 * strtod on the same numbers, in the same run, from C against the static library.
 *
 * 2 000 random frames with origins (Fanuc G68.2: six numbers a line) are written with 4
 * decimals and with the shortest digits that read back, and those lines are read back.
 * glibc does the number part only (snprintf "%.4f" and "%.17g" of the six numbers, strtod
 * over the same line); cncrot's calls do the whole line besides (the angles of the frame
 * when writing, the frame of the angles when reading, the words, the checks). Each figure
 * is the best of several passes over all lines, in nanoseconds per line; the ratio is
 * cncrot's time over glibc's. Usage: benches/text.sh (builds and runs this file). */
#define _POSIX_C_SOURCE 199309L
#include "cncrot.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define LINES 2000
#define PASSES 15

static uint64_t state = 0x2545F4914F6CDD1DULL;
static double uniform(double lo, double hi) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return lo + (hi - lo) * (double)(state >> 11) / 9007199254740992.0;
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static double frames[LINES][16];
static char shortest[LINES][CNCROT_PROGRAM_LINE_MAX + 1];
static char four[LINES][CNCROT_PROGRAM_LINE_MAX + 1];
static double numbers[LINES][6];
static volatile double sink;
static volatile size_t sink_len;

/* The six numbers of a G68.2 line (after X Y Z I J K), read once with strtod. */
static int numbers_of(const char *line, double out[6]) {
    int n = 0;
    for (const char *p = line; *p && n < 6; p++) {
        if (strchr("XYZIJK", *p) && p[-1] == ' ') {
            out[n++] = strtod(p + 1, NULL);
        }
    }
    return n == 6 ? 0 : -1;
}

typedef void (*pass_fn)(void);

static double best(pass_fn f) {
    double b = 1e300;
    for (int r = 0; r < PASSES; r++) {
        double t0 = now();
        f();
        double t = (now() - t0) / LINES;
        if (t < b) b = t;
    }
    return b;
}

static void write_with(int32_t decimals) {
    char out[CNCROT_PROGRAM_LINE_MAX + 1];
    size_t total = 0;
    for (int i = 0; i < LINES; i++) {
        if (cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", frames[i], decimals, out,
                                 sizeof out) < 0) {
            abort();
        }
        total += (size_t)out[5];
    }
    sink_len = total;
}
static void write_four(void) { write_with(4); }
static void write_shortest(void) { write_with(-1); }

static void printf_with(const char *format) {
    char out[64];
    size_t total = 0;
    for (int i = 0; i < LINES; i++) {
        for (int k = 0; k < 6; k++) {
            total += (size_t)snprintf(out, sizeof out, format, numbers[i][k]);
        }
    }
    sink_len = total;
}
static void printf_four(void) { printf_with("%.4f"); }
static void printf_shortest(void) { printf_with("%.17g"); }

static void read_lines(char lines[LINES][CNCROT_PROGRAM_LINE_MAX + 1]) {
    cncrot_program fresh, p;
    cncrot_program_init(&fresh, 0);
    double total = 0;
    for (int i = 0; i < LINES; i++) {
        p = fresh;
        if (cncrot_program_line(&p, CNCROT_DIALECT_FANUC, lines[i], strlen(lines[i])) < 0) {
            abort();
        }
        total += p.origin[0];
    }
    sink = total;
}
static void read_shortest(void) { read_lines(shortest); }
static void read_four(void) { read_lines(four); }

static void strtod_lines(char lines[LINES][CNCROT_PROGRAM_LINE_MAX + 1]) {
    double total = 0;
    for (int i = 0; i < LINES; i++) {
        const char *p = lines[i];
        while (*p) {
            if ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.') {
                char *end;
                total += strtod(p, &end);
                p = end;
            } else {
                p++;
            }
        }
    }
    sink = total;
}
static void strtod_shortest(void) { strtod_lines(shortest); }
static void strtod_four(void) { strtod_lines(four); }

static int row(const char *what, double ours, const char *peer, double theirs) {
    double ratio = ours / theirs;
    printf("| %-28s | %8.0f ns | %-22s | %8.0f ns | %5.2f |\n", what, ours, peer, theirs,
           ratio);
    return ratio <= 1.0 ? 0 : 1;
}

int main(void) {
    for (int i = 0; i < LINES; i++) {
        double angles[3] = {uniform(-180, 180), uniform(-89, 89), uniform(-180, 180)};
        double origin[3] = {uniform(-500, 500), uniform(-500, 500), uniform(-200, 200)};
        double zero[3] = {0, 0, 0};
        if (cncrot_frame_from_angles(1, 57, angles, origin, zero, frames[i]) != 0) return 1;
        if (cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", frames[i], -1, shortest[i],
                                 sizeof shortest[i]) < 0 ||
            cncrot_program_write(CNCROT_DIALECT_FANUC, "G68.2", frames[i], 4, four[i],
                                 sizeof four[i]) < 0 ||
            numbers_of(shortest[i], numbers[i]) != 0) {
            fprintf(stderr, "setup failed at line %d\n", i);
            return 1;
        }
    }
    printf("text benchmark: %d Fanuc G68.2 lines with origins, best of %d passes\n", LINES,
           PASSES);
    printf("e.g. %s\n     %s\n\n", shortest[0], four[0]);
    printf("| %-28s | %11s | %-22s | %11s | %5s |\n", "cncrot, per line", "time",
           "glibc, same numbers", "time", "ratio");
    printf("|------------------------------|-------------|------------------------|-------------|-------|\n");
    int slower = 0;
    slower += row("write, 4 decimals", best(write_four), "snprintf %.4f x6", best(printf_four));
    slower += row("write, shortest", best(write_shortest), "snprintf %.17g x6",
                  best(printf_shortest));
    slower += row("read, shortest numbers", best(read_shortest), "strtod over the line",
                  best(strtod_shortest));
    slower += row("read, 4-decimal numbers", best(read_four), "strtod over the line",
                  best(strtod_four));
    printf("\n%s\n", slower ? "some ratio is above 1.0" : "every ratio is at most 1.0");
    return 0;
}
