/* params.c - eqs 14-21 of Mai-Duy et al. 2019. */
#include <math.h>
#include "params.h"

ImposedParams params_from_eta_sc(int dim, double eta, double Sc, double m, double kBT,
                                 double n, double rc)
{
    ImposedParams p;
    const double mkn2rc2 = m * kBT * n * n * rc * rc;
    if (dim == 3) {
        p.C = 6.0 * Sc * mkn2rc2 / (5.0 * eta * eta);                       /* eq. 14 */
        p.s = (-9.0 + sqrt(1.0 + 4.0 * p.C)) / 2.0;                         /* eq. 14 */
        const double s = p.s;
        p.gamma = 5.0 * eta * (s + 1) * (s + 2) * (s + 3) * (s + 4) * (s + 5)
                / (16.0 * M_PI * n * n * pow(rc, 5));                        /* eq. 15 */
        p.eta_max = sqrt(3.0 * Sc * mkn2rc2 / 50.0);                        /* eq. 16 */
        p.Sc_min = 50.0 * eta * eta / (3.0 * mkn2rc2);                      /* eq. 17 */
    } else {
        p.C = 3.0 * Sc * mkn2rc2 / (4.0 * eta * eta);                       /* eq. 18 */
        p.s = (-7.0 + sqrt(1.0 + 4.0 * p.C)) / 2.0;                         /* eq. 18 */
        const double s = p.s;
        p.gamma = 4.0 * eta * (s + 1) * (s + 2) * (s + 3) * (s + 4)
                / (3.0 * M_PI * n * n * pow(rc, 4));                         /* eq. 19 */
        p.eta_max = sqrt(Sc * mkn2rc2 / 16.0);                              /* eq. 20 */
        p.Sc_min = 16.0 * eta * eta / mkn2rc2;                              /* eq. 21 */
    }
    p.valid = p.s > 0.0;
    return p;
}
