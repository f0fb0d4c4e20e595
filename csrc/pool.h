/*
** pool.h -- the worker threads that rasterize threaded draws
** (gles_threads_set): one pool per process, grown to the most threads a
** context asks for. A job is one function that threads 0..count-1 run
** once each, with their index, the calling thread as 0; contexts in
** different threads take turns (pool_acquire). Built with GLES_THREADS
** (POSIX threads); without it there is no pool and a context renders on
** its calling thread only.
*/
#ifndef GLES_POOL_H
#define GLES_POOL_H

typedef struct WorkPool WorkPool;
typedef void (*PoolJob)(void *arg, int index);

/* the pool, with at least `threads` threads (the caller among them) where
** they can be started (fewer where not: pool_threads); NULL where not
** even one worker can */
WorkPool *pool_shared(int threads);
/* the caller and the workers */
int pool_threads(const WorkPool *pool);
/* 1 when the pool, with at least `threads` threads, is the caller's until
** pool_release; 0 while another context's job has it, or in a child of
** fork(), which has no workers (the caller then works alone) */
int pool_acquire(WorkPool *pool, int threads);
void pool_release(WorkPool *pool);
/* job(arg, i) on thread i for i in 0..count-1 (count <= pool_threads; 0
** on the caller), between pool_acquire and pool_release */
void pool_run(WorkPool *pool, PoolJob job, void *arg, int count);

#endif
