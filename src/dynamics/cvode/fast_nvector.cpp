#include "dynamics/cvode/fast_nvector.hpp"

#include <algorithm>
#include <cmath>
#include <new>

namespace vi::cvode_detail {
namespace {

inline double* data(N_Vector v) { return NV_DATA_S(v); }
inline sunindextype size(N_Vector v) { return NV_LENGTH_S(v); }

void linear_sum(realtype a, N_Vector x, realtype b, N_Vector y, N_Vector z) {
    const double *xd = data(x), *yd = data(y);
    double* zd = data(z);
    const sunindextype n = size(x);
    for (sunindextype i = 0; i < n; ++i) zd[i] = a * xd[i] + b * yd[i];
}

void constant(realtype c, N_Vector z) { std::fill(data(z), data(z) + size(z), c); }

void prod(N_Vector x, N_Vector y, N_Vector z) {
    const double *xd = data(x), *yd = data(y);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] * yd[i];
}

void div(N_Vector x, N_Vector y, N_Vector z) {
    const double *xd = data(x), *yd = data(y);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] / yd[i];
}

void scale(realtype c, N_Vector x, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = c * xd[i];
}

void abs_value(N_Vector x, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = std::abs(xd[i]);
}

void inv(N_Vector x, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = 1.0 / xd[i];
}

void add_const(N_Vector x, realtype b, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = xd[i] + b;
}

realtype dot(N_Vector x, N_Vector y) {
    const double *xd = data(x), *yd = data(y);
    double s = 0.0;
    for (sunindextype i = 0, n = size(x); i < n; ++i) s += xd[i] * yd[i];
    return s;
}

realtype max_norm(N_Vector x) {
    const double* xd = data(x);
    double m = 0.0;
    for (sunindextype i = 0, n = size(x); i < n; ++i) m = std::max(m, std::abs(xd[i]));
    return m;
}

realtype wsqr_sum(N_Vector x, N_Vector w) {
    const double *xd = data(x), *wd = data(w);
    double s = 0.0;
    for (sunindextype i = 0, n = size(x); i < n; ++i) {
        const double p = xd[i] * wd[i];
        s += p * p;
    }
    return s;
}

realtype wrms_norm(N_Vector x, N_Vector w) { return std::sqrt(wsqr_sum(x, w) / static_cast<double>(size(x))); }

realtype wsqr_sum_mask(N_Vector x, N_Vector w, N_Vector id) {
    const double *xd = data(x), *wd = data(w), *md = data(id);
    double s = 0.0;
    for (sunindextype i = 0, n = size(x); i < n; ++i) {
        if (md[i] > 0.0) {
            const double p = xd[i] * wd[i];
            s += p * p;
        }
    }
    return s;
}

realtype wrms_norm_mask(N_Vector x, N_Vector w, N_Vector id) {
    return std::sqrt(wsqr_sum_mask(x, w, id) / static_cast<double>(size(x)));
}

realtype min_value(N_Vector x) {
    const double* xd = data(x);
    double m = xd[0];
    for (sunindextype i = 1, n = size(x); i < n; ++i) m = std::min(m, xd[i]);
    return m;
}

void compare(realtype c, N_Vector x, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    for (sunindextype i = 0, n = size(x); i < n; ++i) zd[i] = std::abs(xd[i]) >= c ? 1.0 : 0.0;
}

booleantype inv_test(N_Vector x, N_Vector z) {
    const double* xd = data(x);
    double* zd = data(z);
    bool ok = true;
    for (sunindextype i = 0, n = size(x); i < n; ++i) {
        if (xd[i] == 0.0) {
            ok = false;
        } else {
            zd[i] = 1.0 / xd[i];
        }
    }
    return ok ? SUNTRUE : SUNFALSE;
}

int linear_combination(int nvec, realtype* c, N_Vector* x, N_Vector z) {
    double* zd = data(z);
    const sunindextype n = size(z);
    // z may be x[0] (in place): then it is scaled first and the rest added.
    if (x[0] == z) {
        if (c[0] != 1.0) {
            for (sunindextype i = 0; i < n; ++i) zd[i] *= c[0];
        }
    } else {
        const double* x0 = data(x[0]);
        for (sunindextype i = 0; i < n; ++i) zd[i] = c[0] * x0[i];
    }
    for (int k = 1; k < nvec; ++k) {
        const double* xk = data(x[k]);
        const double ck = c[k];
        for (sunindextype i = 0; i < n; ++i) zd[i] += ck * xk[i];
    }
    return 0;
}

int scale_add_multi(int nvec, realtype* a, N_Vector x, N_Vector* y, N_Vector* z) {
    const double* xd = data(x);
    const sunindextype n = size(x);
    for (int k = 0; k < nvec; ++k) {
        const double* yd = data(y[k]);
        double* zd = data(z[k]);
        const double ak = a[k];
        for (sunindextype i = 0; i < n; ++i) zd[i] = ak * xd[i] + yd[i];
    }
    return 0;
}

int dot_prod_multi(int nvec, N_Vector x, N_Vector* y, realtype* d) {
    for (int k = 0; k < nvec; ++k) d[k] = dot(x, y[k]);
    return 0;
}

int linear_sum_arrays(int nvec, realtype a, N_Vector* x, realtype b, N_Vector* y, N_Vector* z) {
    for (int k = 0; k < nvec; ++k) linear_sum(a, x[k], b, y[k], z[k]);
    return 0;
}

int scale_arrays(int nvec, realtype* c, N_Vector* x, N_Vector* z) {
    for (int k = 0; k < nvec; ++k) scale(c[k], x[k], z[k]);
    return 0;
}

int const_arrays(int nvec, realtype c, N_Vector* z) {
    for (int k = 0; k < nvec; ++k) constant(c, z[k]);
    return 0;
}

int wrms_norm_arrays(int nvec, N_Vector* x, N_Vector* w, realtype* norms) {
    for (int k = 0; k < nvec; ++k) norms[k] = wrms_norm(x[k], w[k]);
    return 0;
}

}  // namespace

N_Vector new_fast_vector(sunindextype n, SUNContext ctx) {
    N_Vector v = N_VNew_Serial(n, ctx);
    if (!v) throw std::bad_alloc();
    N_Vector_Ops ops = v->ops;
    ops->nvlinearsum = linear_sum;
    ops->nvconst = constant;
    ops->nvprod = prod;
    ops->nvdiv = div;
    ops->nvscale = scale;
    ops->nvabs = abs_value;
    ops->nvinv = inv;
    ops->nvaddconst = add_const;
    ops->nvdotprod = dot;
    ops->nvmaxnorm = max_norm;
    ops->nvwrmsnorm = wrms_norm;
    ops->nvwrmsnormmask = wrms_norm_mask;
    ops->nvmin = min_value;
    ops->nvcompare = compare;
    ops->nvinvtest = inv_test;
    ops->nvwsqrsumlocal = wsqr_sum;
    ops->nvwsqrsummasklocal = wsqr_sum_mask;
    ops->nvdotprodlocal = dot;
    ops->nvmaxnormlocal = max_norm;
    ops->nvminlocal = min_value;
    ops->nvinvtestlocal = inv_test;
    ops->nvlinearcombination = linear_combination;
    ops->nvscaleaddmulti = scale_add_multi;
    ops->nvdotprodmulti = dot_prod_multi;
    ops->nvlinearsumvectorarray = linear_sum_arrays;
    ops->nvscalevectorarray = scale_arrays;
    ops->nvconstvectorarray = const_arrays;
    ops->nvwrmsnormvectorarray = wrms_norm_arrays;
    return v;
}

}  // namespace vi::cvode_detail
