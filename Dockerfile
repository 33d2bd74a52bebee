# One environment for students (VS Code or Codespaces, .devcontainer/), the
# grader and CI: Debian 12 with the packages the course's own install step
# (make deps, through tools/build/deps.sh) puts there. Build and enter it:
#   docker build -t raytracer . && docker run --rm -it -v "$PWD":/course raytracer
# then `make` and `make test` inside. DEPS names the make targets that
# install packages: the build's alone by default; add grade-deps for the
# grader, clang-deps for make sanitize.
FROM debian:bookworm-slim
ARG DEPS=deps
ENV DEBIAN_FRONTEND=noninteractive
# make and a compiler to run the install step; git for the grader (it reads
# git ls-files); ca-certificates for apt over https mirrors.
RUN apt-get update \
 && apt-get install -y --no-install-recommends make gcc libc6-dev git ca-certificates \
 && rm -rf /var/lib/apt/lists/*
WORKDIR /course
# The install step alone first, so that a change to the course's sources
# does not install the packages again.
COPY Makefile ./
COPY mk/ mk/
COPY tools/build/deps.sh tools/
RUN make $DEPS && rm -rf build && rm -rf /var/lib/apt/lists/*
COPY . .
CMD ["bash"]
