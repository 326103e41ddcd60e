vec3 runningMean(vec3 mean, uint count, vec3 sum, uint newCount) {
    return 0.5 * (mean + sum / float(newCount));
}
