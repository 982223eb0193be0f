/* GRPVSS inverse-kinematics plug-in ABI (C, no GRPVSS headers needed). See docs/ik-plugin.md.
 *
 * A plug-in is a shared library exporting the functions below with C linkage. Units are the
 * library's: lengths as in the robot file, revolute joint values in RADIANS. */
#ifndef GRPVSS_KINEMATICS_IK_PLUGIN_H
#define GRPVSS_KINEMATICS_IK_PLUGIN_H

#ifdef __cplusplus
extern "C" {
#endif

/** The ABI version this header describes; grpvss_ik_abi_version() must return it. */
#define GRPVSS_IK_ABI_VERSION 1

/** Return codes of grpvss_ik_solve. */
#define GRPVSS_IK_SOLVED 0
#define GRPVSS_IK_OUT_OF_WORKSPACE 1

/** Required: returns GRPVSS_IK_ABI_VERSION. */
int grpvss_ik_abi_version(void);

/** Required: solves for the joint values placing the end-effector frame at X_WE.
 *  X_WE:   4x4 homogeneous pose of the end effector in the world, ROW-MAJOR (X_WE[4*r + c]).
 *  q_near: n joint values; among several solutions return the one nearest to them.
 *  n:      number of joints of the robot.
 *  q_out:  n joint values written when solved (within the joint limits).
 *  Returns GRPVSS_IK_SOLVED or GRPVSS_IK_OUT_OF_WORKSPACE; anything else is an error. */
int grpvss_ik_solve(const double X_WE[16], const double* q_near, int n, double* q_out);

/** Optional: a short name for messages (static storage). */
const char* grpvss_ik_name(void);

#ifdef __cplusplus
}
#endif

#endif /* GRPVSS_KINEMATICS_IK_PLUGIN_H */
