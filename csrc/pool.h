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
/* 1 when the pool, with at least `threads` threads, is the caller's for
** one job (pool_start or pool_run; its end gives the pool back); 0 while
** another job has it, or in a child of fork(), which has no workers (the
** caller then works alone) */
int pool_acquire(WorkPool *pool, int threads);
/* job(arg, i) on thread i for i in 0..count-1 (count <= pool_threads; 0
** on the caller), after pool_acquire; returns when all are done */
void pool_run(WorkPool *pool, PoolJob job, void *arg, int count);
/* pool_run without the wait: returns when share 0 is done, the workers'
** shares perhaps still running, with the job's ticket for pool_wait */
unsigned long pool_start(WorkPool *pool, PoolJob job, void *arg, int count);
/* waits for the job of `ticket` to end: 1 where it had not yet */
int pool_wait(WorkPool *pool, unsigned long ticket);

#endif
