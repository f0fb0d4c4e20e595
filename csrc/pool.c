/*
** pool.c -- the process's worker threads (pool.h).
** Owns: starting and waking the workers. A job's generation number wakes
**       them; each runs its share once (or none, past the job's count) and
**       the last one done marks the job finished, gives the pool back
**       and wakes whoever waits for it: the caller ran share 0 meanwhile
**       and may have gone on to other work (pool_start, pool_wait).
**       The pool lives as long as the process: contexts come and go, and
**       a program with many of them keeps one set of threads.
*/
#include "gles_core.h"
#include "pool.h"

#if GLES_THREADS
#include <pthread.h>
#include <stdatomic.h>

/* a worker done with a job watches for the next one this many times
** before it sleeps, and the caller watches for the workers' end as long:
** a frame's draws follow each other within microseconds, and waking a
** sleeping thread takes tens of them (benchmarks/README.md) */
#define POOL_SPINS 20000

static inline void pool_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

typedef struct PoolWorker {
    WorkPool *pool;
    int index;
    unsigned long start;        /* the generation before its first job */
    pthread_t thread;
} PoolWorker;

struct WorkPool {
    pthread_mutex_t lock;
    pthread_cond_t wake, done;
    /* 1 from pool_acquire to the end of the job started then (its last
    ** worker clears it): a flag, not a mutex, since that is another
    ** thread than the one that took it */
    atomic_int busy;
    pthread_mutex_t growing;    /* held while workers are started */
    atomic_ulong generation;    /* advances per job */
    atomic_ulong finished;      /* the generation of the last job done */
    atomic_int running;         /* workers still on the current job */
    int sleeping;               /* workers waiting on `wake` (under lock) */
    PoolJob job;
    void *arg;
    int count;                  /* the job's shares */
    int threads;                /* the caller and the workers started */
    PoolWorker workers[GLES_MAX_THREADS];   /* 1..threads - 1 */
};

/* the next job's generation after `seen` */
static unsigned long pool_next(WorkPool *pool, unsigned long seen)
{
    for (int i = 0; i < POOL_SPINS; i++) {
        if (atomic_load_explicit(&pool->generation, memory_order_acquire) != seen)
            return atomic_load_explicit(&pool->generation, memory_order_acquire);
        pool_relax();
    }
    pthread_mutex_lock(&pool->lock);
    pool->sleeping++;
    while (atomic_load(&pool->generation) == seen)
        pthread_cond_wait(&pool->wake, &pool->lock);
    pool->sleeping--;
    const unsigned long next = atomic_load(&pool->generation);
    pthread_mutex_unlock(&pool->lock);
    return next;
}

static void *pool_main(void *p)
{
    PoolWorker *w = p;
    WorkPool *pool = w->pool;
    unsigned long seen = w->start;
    for (;;) {
        seen = pool_next(pool, seen);
        if (w->index < pool->count)
            pool->job(pool->arg, w->index);
        if (atomic_fetch_sub_explicit(&pool->running, 1, memory_order_acq_rel) == 1) {
            /* the job's last worker: finished before the wake-up (a waiter
            ** tests it under the lock), then the pool free for the next */
            atomic_store_explicit(&pool->finished, seen, memory_order_release);
            pthread_mutex_lock(&pool->lock);
            pthread_cond_broadcast(&pool->done);
            pthread_mutex_unlock(&pool->lock);
            atomic_store_explicit(&pool->busy, 0, memory_order_release);
        }
    }
    return NULL;
}

static WorkPool shared_pool = { .lock = PTHREAD_MUTEX_INITIALIZER, .wake = PTHREAD_COND_INITIALIZER,
                                .done = PTHREAD_COND_INITIALIZER, .growing = PTHREAD_MUTEX_INITIALIZER,
                                .threads = 1 };

/* a child of fork() has none of the workers: its pool starts over empty
** (contexts there work alone until they ask for threads again) */
static void pool_after_fork(void)
{
    WorkPool *pool = &shared_pool;
    pthread_mutex_init(&pool->lock, NULL);
    pthread_mutex_init(&pool->growing, NULL);
    atomic_store(&pool->busy, 0);
    pthread_cond_init(&pool->wake, NULL);
    pthread_cond_init(&pool->done, NULL);
    atomic_store(&pool->running, 0);
    atomic_store(&pool->finished, atomic_load(&pool->generation));   /* (the parent waited for it) */
    pool->sleeping = 0;
    pool->threads = 1;
}

/* a job still running when the process forks finishes first: the child
** then holds every row its draws asked for */
static void pool_before_fork(void) { pool_wait(&shared_pool, atomic_load(&shared_pool.generation)); }

/* 1 where the pool was free and is now the caller's */
static int pool_take(WorkPool *pool)
{
    int expected = 0;
    return atomic_compare_exchange_strong_explicit(&pool->busy, &expected, 1, memory_order_acquire,
                                                   memory_order_relaxed);
}

static pthread_once_t pool_once = PTHREAD_ONCE_INIT;
static void pool_init(void) { pthread_atfork(pool_before_fork, NULL, pool_after_fork); }

WorkPool *pool_shared(int threads)
{
    WorkPool *pool = &shared_pool;
    pthread_once(&pool_once, pool_init);
    if (threads > GLES_MAX_THREADS)
        threads = GLES_MAX_THREADS;
    /* no job runs while workers join (each starts at the current
    ** generation): the pool taken as pool_acquire takes it, waiting */
    pthread_mutex_lock(&pool->growing);
    while (!pool_take(pool))
        pool_relax();
    while (pool->threads < threads) {
        PoolWorker *w = &pool->workers[pool->threads];
        w->pool = pool;
        w->index = pool->threads;
        w->start = atomic_load(&pool->generation);
        if (pthread_create(&w->thread, NULL, pool_main, w))
            break;
        pthread_detach(w->thread);
        pool->threads++;
    }
    const int have = pool->threads;
    atomic_store_explicit(&pool->busy, 0, memory_order_release);
    pthread_mutex_unlock(&pool->growing);
    return have >= 2 ? pool : NULL;
}

int pool_threads(const WorkPool *pool) { return pool->threads; }

int pool_acquire(WorkPool *pool, int threads)
{
    if (!pool_take(pool))
        return 0;
    if (pool->threads < threads) {
        /* fewer workers than the context was given (a child of fork()) */
        atomic_store_explicit(&pool->busy, 0, memory_order_release);
        return 0;
    }
    return 1;
}

unsigned long pool_start(WorkPool *pool, PoolJob job, void *arg, int count)
{
    /* the job is in place before the generation that announces it (release) */
    pool->job = job;
    pool->arg = arg;
    pool->count = count;
    atomic_store_explicit(&pool->running, pool->threads - 1, memory_order_relaxed);
    pthread_mutex_lock(&pool->lock);
    const unsigned long ticket = atomic_fetch_add_explicit(&pool->generation, 1, memory_order_release) + 1;
    if (pool->sleeping)
        pthread_cond_broadcast(&pool->wake);
    pthread_mutex_unlock(&pool->lock);
    job(arg, 0);
    return ticket;
}

/* whether the job of generation `ticket` (or a later one) is done */
static int pool_finished(WorkPool *pool, unsigned long ticket)
{
    return atomic_load_explicit(&pool->finished, memory_order_acquire) >= ticket;
}

int pool_wait(WorkPool *pool, unsigned long ticket)
{
    if (pool_finished(pool, ticket))
        return 0;
    for (int i = 0; i < POOL_SPINS && !pool_finished(pool, ticket); i++)
        pool_relax();
    if (!pool_finished(pool, ticket)) {
        pthread_mutex_lock(&pool->lock);
        while (!pool_finished(pool, ticket))
            pthread_cond_wait(&pool->done, &pool->lock);
        pthread_mutex_unlock(&pool->lock);
    }
    return 1;
}

void pool_run(WorkPool *pool, PoolJob job, void *arg, int count) { pool_wait(pool, pool_start(pool, job, arg, count)); }

#else

WorkPool *pool_shared(int threads)
{
    (void)threads;
    return NULL;
}

int pool_threads(const WorkPool *pool)
{
    (void)pool;
    return 1;
}

int pool_acquire(WorkPool *pool, int threads)
{
    (void)pool;
    (void)threads;
    return 0;
}

unsigned long pool_start(WorkPool *pool, PoolJob job, void *arg, int count)
{
    (void)pool;
    (void)count;
    job(arg, 0);
    return 0;
}

int pool_wait(WorkPool *pool, unsigned long ticket)
{
    (void)pool;
    (void)ticket;
    return 0;
}

void pool_run(WorkPool *pool, PoolJob job, void *arg, int count) { pool_start(pool, job, arg, count); }

#endif
