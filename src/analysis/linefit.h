/* linefit.h - `dpd fit-line`: weighted least-squares straight line through
 * columns of a tab-separated table (GSL gsl_fit_wlinear), e.g. the bulk of a
 * Couette velocity profile. */
#ifndef DPD_LINEFIT_H
#define DPD_LINEFIT_H

int cmd_fit_line(int argc, char **argv);

#endif
