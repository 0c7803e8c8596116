/*
 * version.h: loft's version, the one place it is kept.  Every program's
 * --version prints it (loft_opt_long, run.c); a release changes it here.
 */
#ifndef LOFT_VERSION_H
#define LOFT_VERSION_H

#define LOFT_VERSION "0.1"

#endif
