/*
 * contact_user.h: the C ABI of NORMAL_ROUTINE and FRICTION_ROUTINE user routines.
 *
 * A CONTACT names a routine as NORMAL_ROUTINE = library::function (FRICTION_ROUTINE likewise),
 * with its constants in NORMAL_FUNCTION = USER(r1, ..., r30). The library is a shared library:
 * a path (relative to the dataset's directory) or a bare NAME, loaded as libNAME.so,
 * libNAME.dylib or NAME.dll from the dataset's directory, then from the loader's search path.
 *
 * The function is called once per contact (intersection region) per evaluation, possibly from
 * several threads at once: it must not keep mutable state between calls. Vectors are in world
 * coordinates; the normal points from J into I. Pointers are valid during the call only.
 *
 * A normal routine writes output[0], the normal force magnitude (positive pushes I along the
 * normal; it is not clamped). A friction routine writes output[0..2], the friction force on I,
 * and output[3], the torque on I about the normal; J receives the opposite. Return 0 on
 * success; any other value stops the run with an error naming the contact, routine and code.
 * A non-finite output is an error too.
 */
#ifndef CONTACT_USER_H
#define CONTACT_USER_H

#include <stdint.h>

#define CONTACT_USER_ABI_VERSION 1

struct contact_user_input {
    uint32_t abi_version;      /* CONTACT_USER_ABI_VERSION */
    uint32_t index;            /* which contact of the pair, 0-based */
    double time;
    double point_i[3];         /* contact point on I's surface */
    double point_j[3];         /* contact point on J's surface */
    double normal[3];          /* unit normal, J into I */
    double penetration;        /* >= 0 */
    double penetration_rate;   /* > 0 while approaching */
    double area;               /* contact area estimate */
    double slip_velocity[3];   /* tangential velocity of I against J at the contact */
    double spin;               /* relative angular velocity of I against J about the normal */
    double normal_force;       /* 0 for a normal routine; the normal force for friction */
    const double *parameters;  /* the USER constants (NULL when none) */
    uint32_t parameter_count;
    uint32_t reserved;
};

typedef int32_t (*contact_user_routine)(const struct contact_user_input *input, double *output);

#endif
