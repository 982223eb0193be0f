/* Example GRPVSS IK plug-in: closed-form IK of the IBM 7545 of data/ibm7545/robot.txt,
 * written against the C ABI only (docs/ik-plugin.md shows this file). Compile definitions
 * produce the broken variants the loader tests need:
 *   GRPVSS_TEST_OMIT_SOLVE      -> no grpvss_ik_solve symbol
 *   GRPVSS_TEST_WRONG_ABI       -> grpvss_ik_abi_version() returns 99
 *   GRPVSS_TEST_BAD_RETURN_CODE -> grpvss_ik_solve() returns 7 */
#include <math.h>

#include "grpvss/kinematics/ik_plugin.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

int grpvss_ik_abi_version(void) {
#ifdef GRPVSS_TEST_WRONG_ABI
  return 99;
#else
  return GRPVSS_IK_ABI_VERSION;
#endif
}

const char* grpvss_ik_name(void) { return "IBM 7545 example plug-in"; }

#ifndef GRPVSS_TEST_OMIT_SOLVE
/* DH of the IBM 7545: d1, a1, a2, d4 and the joint limits. */
static const double d1 = 25.5, a1 = 15.8, a2 = 9.8, d4 = 15.05;
static const double q_min[4] = {0.0, 0.0, 0.0, -180.0 * DEG};
static const double q_max[4] = {200.0 * DEG, 135.0 * DEG, 9.8, 180.0 * DEG};

static int within(int i, double* q) {
  const double slack = 1e-10;
  if (q[i] < q_min[i] - slack || q[i] > q_max[i] + slack) return 0;
  if (q[i] < q_min[i]) q[i] = q_min[i];
  if (q[i] > q_max[i]) q[i] = q_max[i];
  return 1;
}

int grpvss_ik_solve(const double X_WE[16], const double* q_near, int n, double* q_out) {
#ifdef GRPVSS_TEST_BAD_RETURN_CODE
  return 7;
#endif
  double best_distance = INFINITY;
  int found = 0;
  if (n != 4) return GRPVSS_IK_OUT_OF_WORKSPACE;
  /* Row-major: X_WE[4*r + c]. The tool z axis (third column) must point down. */
  if (fabs(X_WE[2]) > 1e-9 || fabs(X_WE[6]) > 1e-9 || fabs(X_WE[10] + 1.0) > 1e-9) {
    return GRPVSS_IK_OUT_OF_WORKSPACE;
  }
  const double x = X_WE[3], y = X_WE[7], z = X_WE[11];
  const double yaw = atan2(X_WE[4], X_WE[0]);
  double c2 = (x * x + y * y - a1 * a1 - a2 * a2) / (2 * a1 * a2);
  if (fabs(c2) > 1 + 1e-12) return GRPVSS_IK_OUT_OF_WORKSPACE;
  if (c2 > 1) c2 = 1;
  if (c2 < -1) c2 = -1;
  for (int branch = 0; branch < 2; ++branch) {
    double q[4];
    q[1] = (branch == 0 ? 1.0 : -1.0) * acos(c2);
    q[0] = atan2(y, x) - atan2(a2 * sin(q[1]), a1 + a2 * cos(q[1]));
    q[2] = d1 - d4 - z;
    q[3] = q[0] + q[1] - yaw;
    if (q[0] < q_min[0]) q[0] += 2 * PI; /* atan2 lies in (-pi, pi] */
    if (q[3] > q_max[3]) q[3] -= 2 * PI;
    if (q[3] < q_min[3]) q[3] += 2 * PI;
    if (!within(0, q) || !within(1, q) || !within(2, q) || !within(3, q)) continue;
    double distance = 0;
    for (int i = 0; i < 4; ++i) distance += (q[i] - q_near[i]) * (q[i] - q_near[i]);
    if (distance < best_distance) {
      best_distance = distance;
      for (int i = 0; i < 4; ++i) q_out[i] = q[i];
      found = 1;
    }
  }
  return found ? GRPVSS_IK_SOLVED : GRPVSS_IK_OUT_OF_WORKSPACE;
}
#endif
