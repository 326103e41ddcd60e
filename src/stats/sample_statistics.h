#pragma once
// Means, standard errors and least-squares slopes of samples (tests, convergence plots).
#include <vector>

namespace raylab::stats {

double mean(const std::vector<double>& v);
// Standard error of the mean: sample standard deviation / √n (n ≥ 2).
double standardError(const std::vector<double>& v);
// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y);
// Least-squares slope of log y against log x (an RMSE's convergence rate against samples).
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

} // namespace raylab::stats
