local P = washout.parameters {
  dim = 2,
  alhpa = 0.1,
}
