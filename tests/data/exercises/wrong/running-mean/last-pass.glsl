vec3 runningMean(vec3 mean, uint count, vec3 sum, uint newCount) {
    return sum / float(newCount);
}
