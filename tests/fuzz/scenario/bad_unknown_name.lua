track {
  segments = {
    tangnet { length = 30 },
  },
}
