/* params.h - imposing viscosity and Schmidt number through w_D = (1-r/rc)^s
 * (Mai-Duy, Phan-Thien & Tran-Cong 2017; Mai-Duy et al. 2019, eqs 14-21). */
#ifndef DPD_PARAMS_H
#define DPD_PARAMS_H

typedef struct {
    double s, gamma, C;
    double eta_max;           /* eq. 16 (3D) / eq. 20 (2D): s > 0 needs eta below this */
    double Sc_min;            /* eq. 17 (3D) / eq. 21 (2D) */
    int valid;                /* s > 0 */
} ImposedParams;

ImposedParams params_from_eta_sc(int dim, double eta, double Sc, double m, double kBT,
                                 double n, double rc);

#endif
