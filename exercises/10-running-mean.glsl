// Exercise running-mean · level VWO 5-6 · about 20 minutes.
// The image is the mean of all samples so far, kept up to date pass after pass without storing
// the samples. (pbrt-v4 §2.1.1 Monte Carlo estimator; Welford 1962, the running mean.)
//
// mean is the mean of the count samples so far (when count is 0 it is 0 and means nothing); sum
// is the sum of newCount new samples. Return the mean of all count + newCount samples. Mind the
// precision: after thousands of passes, adding small corrections to the old mean rounds better
// than re-adding huge sums.
vec3 runningMean(vec3 mean, uint count, vec3 sum, uint newCount) {
    return sum;   // replace
}
