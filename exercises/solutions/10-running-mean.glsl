// Exercise running-mean: a solution (the update mean + (sum − k·mean) / (n + k)).
vec3 runningMean(vec3 mean, uint count, vec3 sum, uint newCount) {
    return mean + (sum - float(newCount) * mean) / float(count + newCount);
}
